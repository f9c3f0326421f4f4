// The fill table (core/fill_table.hpp): plane offsets over (tilt row, volume column) in
// an R32F texture, interpolated exactly as FillTable::offset_at. Texels are fetched one
// by one: ES 3.0 does not filter float textures.
uniform highp sampler2D u_fill_table;

const int TABLE_TILTS = 64;
const int TABLE_VOLUMES = 64;
const float TABLE_MAX_TILT = 0.75 * PI;

float table_row(int row, int j, float fj) {
  return mix(texelFetch(u_fill_table, ivec2(j, row), 0).r, texelFetch(u_fill_table, ivec2(j + 1, row), 0).r, fj);
}

float fill_table_offset(float tilt, float fraction) {
  float ti = clamp(tilt / TABLE_MAX_TILT, 0.0, 1.0) * float(TABLE_TILTS - 1);
  float u = 0.5 - sin(asin(1.0 - 2.0 * clamp(fraction, 0.0, 1.0)) / 3.0);  // inverse of u^2 (3 - 2u)
  float vj = u * float(TABLE_VOLUMES - 1);
  int i = min(int(ti), TABLE_TILTS - 2), j = min(int(vj), TABLE_VOLUMES - 2);
  float fi = ti - float(i), fj = vj - float(j);
  float row_step = TABLE_MAX_TILT / float(TABLE_TILTS - 1);
  float level = table_row(0, j, fj);
  float r0 = table_row(i, j, fj) - cos(float(i) * row_step) * level;
  float r1 = table_row(i + 1, j, fj) - cos(float(i + 1) * row_step) * level;
  return cos(tilt) * level + mix(r0, r1, fi);
}

// The surface plane's offset for its tilt and the volume, never above the lowest rim
// point (as core/simulation.cpp); -1 when the glass is empty.
float liquid_offset() {
  if (u_liquid.w < 0.5) return -1.0;
  vec3 n = u_liquid_plane.xyz;
  float tilt = atan(length(n.xz), n.y);
  float rim = cos(tilt) * u_vessel.x - sin(tilt) * u_knots[SEGMENTS].y;
  return min(fill_table_offset(tilt, u_liquid_plane.w), rim);
}


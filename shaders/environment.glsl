// Surroundings: a procedural photo studio (gradient sky, key softbox, two vertical
// strip lights, a glow behind the glass) or a constant colour, plus a checker floor
// that receives the glass's tinted shadow and a caustic.

vec3 studio_sky(vec3 d) {
  if (u_env.x > 0.5) return u_env_color.rgb;
  vec3 sky = d.y >= 0.0 ? mix(u_sky_horizon.rgb, u_sky_top.rgb, pow(d.y, 0.6))
                        : mix(u_sky_horizon.rgb, u_ground.rgb, smoothstep(0.0, 0.25, -d.y));
  // Strip lights, left and right and a little behind the glass, tall and narrow.
  for (int i = 0; i < 2; ++i) {
    float az = radians(i == 0 ? 105.0 : -105.0);
    vec2 sd = vec2(sin(az), cos(az));
    float horiz = length(d.xz);
    float c = horiz > 1e-4 ? dot(d.xz / horiz, sd) : 0.0;
    float across = smoothstep(0.985, 0.996, c);
    float along = smoothstep(-0.15, 0.0, d.y) * (1.0 - smoothstep(0.55, 0.75, d.y));
    sky += vec3(u_env.y) * across * along;
  }
  // The glow on the backdrop behind the glass.
  vec3 g = normalize(vec3(0.0, 0.12, -1.0));
  float cg = max(dot(d, g), 0.0);
  sky += u_env.z * vec3(1.0, 0.97, 0.92) * pow(cg, 200.0);
  // The key softbox.
  float ck = dot(d, normalize(u_light_dir.xyz));
  sky += u_light_color.rgb * u_light_dir.w * 2.0 * smoothstep(u_light_color.w - 0.004, u_light_color.w + 0.004, ck);
  return sky;
}

// Mean light arriving from the upper hemisphere (for the floor and the haze).
vec3 ambient_light() {
  if (u_env.x > 0.5) return u_env_color.rgb;
  return 0.5 * (u_sky_top.rgb + u_sky_horizon.rgb);
}

// Light reaching a floor point past the glass: a soft shadow tinted by the drink, with
// the glass focusing light into a caustic in the middle of it. Analytic: the glass is
// taken as a cylinder of its mean radius for this purpose. p in the glass's frame.
vec3 floor_light_transmission(vec3 p) {
  vec3 l = to_local_dir(normalize(u_light_dir.xyz));
  float rad = u_glass.w;
  // Closest approach of the shadow ray p + s l to the axis.
  vec2 dxz = l.xz;
  float a = dot(dxz, dxz);
  if (a < 1e-8) return vec3(1.0);
  float s = -dot(p.xz, dxz) / a;
  float dist = length(p.xz + s * dxz);
  float y = p.y + s * l.y;
  if (s <= 0.0 || y > u_vessel.x + 0.004) return vec3(1.0);
  float edge = smoothstep(rad * 1.05, rad * 0.9, dist);
  if (edge <= 0.0) return vec3(1.0);
  float chord = 2.0 * sqrt(max(rad * rad - dist * dist, 0.0));
  bool wet = u_liquid.w > 0.5 && liquid_level(vec3(0.0, y, 0.0)) < 0.0;
  vec3 through = wet ? exp(-u_liquid_absorb.rgb * chord) : vec3(0.85);
  float x = dist / rad;
  float caustic = wet ? 0.45 + 1.6 * pow(max(1.0 - x * x, 0.0), 6.0) : 0.75;
  return mix(vec3(1.0), through * caustic, edge);
}

// p in the glass's frame; the checker is laid out in the world.
vec3 shade_floor(vec3 p, float dist) {
  vec2 cell = floor(to_world_point(p).xz / u_floor_a.w);
  bool light_square = mod(cell.x + cell.y, 2.0) < 0.5;
  vec3 albedo = light_square ? u_floor_a.rgb : u_floor_b.rgb;
  vec3 l = normalize(u_light_dir.xyz);
  // Contact shadow: darker near the foot (which lifts off the floor when the glass tips).
  float foot_dist = length(vec2(max(length(p.xz) - u_rim.w, 0.0), p.y));
  float contact = 1.0 - 0.55 * exp(-foot_dist / (0.25 * u_rim.w));
  vec3 light = ambient_light() * contact + u_light_color.rgb * u_light_dir.w * max(l.y, 0.0) * floor_light_transmission(p);
  vec3 c = albedo * light / PI * 1.6;
  // Far floor fades into the studio backdrop, so the checker never aliases at the horizon.
  return mix(u_ground.rgb, c, exp(-dist / 2.0));
}

// Everything that is not the glass: floor where the ray meets it, else the sky. The
// ray is in the glass's frame.
vec3 background(vec3 o, vec3 d) {
  vec3 wd = to_world_dir(d);
  if (u_env.w > 0.5 && wd.y < 0.0) {
    float t = -to_world_point(o).y / wd.y;
    if (t > 0.0) return shade_floor(o + t * d, t);
  }
  return studio_sky(wd);
}

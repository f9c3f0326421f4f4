// Numbers and root solvers every part of the shader library uses. The solvers mirror
// core/reference/intersect.cpp (solve_quadratic, solve_cubic, solve_quartic), which
// tests compare with the GPU through the probes.
#ifndef LIB_COMMON_MATH_GLSL
#define LIB_COMMON_MATH_GLSL
precision highp float;
precision highp int;

const float PI = 3.14159265358979;
const float INF = 1e30;

// Real roots of a x^2 + b x + c, ascending (numerically stable form).
int solve_quadratic(float a, float b, float c, out vec2 x) {
  x = vec2(INF);
  if (abs(a) < 1e-20) {
    if (abs(b) < 1e-20) return 0;
    x = vec2(-c / b, INF);
    return 1;
  }
  float disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 0;
  float sq = sqrt(disc);
  float q = -0.5 * (b + (b >= 0.0 ? sq : -sq));
  float x0 = q / a, x1 = q != 0.0 ? c / q : x0;
  x = vec2(min(x0, x1), max(x0, x1));
  return 2;
}

// Real roots of x^3 + a x^2 + b x + c: returns the largest.
float cubic_largest_root(float a, float b, float c) {
  float Q = (a * a - 3.0 * b) / 9.0, R = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
  float Q3 = Q * Q * Q;
  if (R * R < Q3) {
    float th = acos(clamp(R / sqrt(Q3), -1.0, 1.0));
    float sq = -2.0 * sqrt(Q);
    return max(max(sq * cos(th / 3.0), sq * cos((th + 2.0 * PI) / 3.0)), sq * cos((th - 2.0 * PI) / 3.0)) -
           a / 3.0;
  }
  float A = -sign(R) * pow(abs(R) + sqrt(R * R - Q3), 1.0 / 3.0);
  float B = A != 0.0 ? Q / A : 0.0;
  return A + B - a / 3.0;
}

// Real roots of x^4 + b x^3 + c x^2 + d x + e (Ferrari), Newton-polished; unsorted,
// missing roots are INF.
vec4 solve_quartic(float b, float c, float d, float e) {
  float b2 = b * b;
  float p = c - 3.0 * b2 / 8.0;
  float q = d - b * c / 2.0 + b2 * b / 8.0;
  float r = e - b * d / 4.0 + b2 * c / 16.0 - 3.0 * b2 * b2 / 256.0;
  vec4 roots = vec4(INF);
  vec2 x;
  // Near q = 0 Ferrari's m -> 0 and q / sqrt(m) is noise: solve the biquadratic instead
  // and let the Newton polish restore q (as core/reference/intersect.cpp).
  float scale = max(1.0, max(abs(p), sqrt(abs(r))));
  float m = abs(q) > 1e-7 * scale * sqrt(scale) ? cubic_largest_root(p, p * p / 4.0 - r, -q * q / 8.0) : 0.0;
  if (m <= 1e-6 * scale) {
    int k = solve_quadratic(1.0, p, r, x);
    if (k > 0 && x.x >= 0.0) roots.xy = vec2(sqrt(x.x), -sqrt(x.x));
    if (k > 1 && x.y >= 0.0) roots.zw = vec2(sqrt(x.y), -sqrt(x.y));
  } else {
    float s = sqrt(2.0 * m);
    if (solve_quadratic(1.0, -s, p / 2.0 + m + q / (2.0 * s), x) > 0) roots.xy = x;
    if (solve_quadratic(1.0, s, p / 2.0 + m - q / (2.0 * s), x) > 0) roots.zw = x;
  }
  for (int i = 0; i < 4; ++i) {
    if (roots[i] >= INF) continue;
    float z = roots[i] - b / 4.0;
    for (int it = 0; it < 2; ++it) {
      float f = (((z + b) * z + c) * z + d) * z + e;
      float df = ((4.0 * z + 3.0 * b) * z + 2.0 * c) * z + d;
      if (df != 0.0) z -= f / df;
    }
    roots[i] = z;
  }
  return roots;
}

#endif  // LIB_COMMON_MATH_GLSL

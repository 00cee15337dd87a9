// kiln/ltc.h: polygonal area lights through a linearly transformed cosine (Heitz, Dupuy, Hill &
// Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines").
//
// Header-only, no exceptions, no global state, no allocation. An LTC table (kind `ltc`,
// runtime/FORMAT.md "LTC tables") stores per (roughness, sqrt(1 - cos theta_o)) the inverse
// matrix M^-1 of the fitted LTC as 4 coefficients (a, b, c, d), M^-1 = [[a, 0, c], [0, 1, 0],
// [b, 0, d]] (rows), and the lobe's norm and Schlick Fresnel term. The matrix acts in the
// shading frame: normal +z, the view in the xz plane with x >= 0 (x = normalize(V - N (N.V)),
// y = N x x).
//
// With E = ltcPolygonIntegral(...) the integral of the fitted (normalised) lobe over the polygon,
// a polygon light of constant radiance L gives  L * E * (F0 * norm + (1 - F0) * fresnel)  for
// Schlick's F with F90 = 1 (the published second texture's use), and L * E * norm for F = 1.
#pragma once

#include <cmath>

namespace kiln {

/// The M^-1 coefficients of one LTC texel as stored: (a, b, c, d) with
/// M^-1 = [[a, 0, c], [0, 1, 0], [b, 0, d]] (row-major), the published ltc_1 channel order.
struct LtcInverse {
  double a = 1, b = 0, c = 0, d = 1;
};

namespace ltc_detail {
struct V3 {
  double x, y, z;
};
inline V3 sub(V3 p, V3 q) noexcept { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
inline double dot(V3 p, V3 q) noexcept { return p.x * q.x + p.y * q.y + p.z * q.z; }
inline V3 cross(V3 p, V3 q) noexcept {
  return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
}
inline V3 scale(V3 p, double s) noexcept { return {p.x * s, p.y * s, p.z * s}; }
inline V3 unit(V3 p) noexcept {
  double l = std::sqrt(dot(p, p));
  return l > 0 ? scale(p, 1 / l) : V3{0, 0, 0};
}
/// The edge integral of the clamped cosine's form factor from unit v1 to unit v2, z component:
/// theta n.z with theta the angle between them and n the unit normal of their great circle
/// (atan2 of |cross| and dot, accurate for short and nearly opposite edges).
inline double edgeZ(V3 v1, V3 v2) noexcept {
  V3 c = cross(v1, v2);
  double s = std::sqrt(dot(c, c));
  if (s <= 0) return 0;
  return std::atan2(s, dot(v1, v2)) * c.z / s;
}
}  // namespace ltc_detail

/// The most vertices ltcPolygonIntegral takes.
constexpr int kLtcMaxVertices = 16;

/// Integral over a polygon of the clamped cosine max(0, z)/pi, after the polygon is mapped by
/// `minv` (any 3x3, row-major; a scale of it does not change the result): vertices `p[i]`
/// (x, y, z in the shading frame, relative to the shaded point; count in [3, kLtcMaxVertices])
/// are transformed by minv, projected to the unit sphere, clipped to z >= 0 and integrated by
/// the edge-integral form (Lambert's, as the paper): E = 1/(2 pi) sum_i theta_i n_i.z. Returns
/// the absolute value when `twoSided`, else the signed value with counter-clockwise polygons
/// (seen from the shaded point) positive, clamped to >= 0. 0 for a bad count.
inline double ltcPolygonIntegral(const double minv[9], const double (*p)[3], int count,
                                 bool twoSided) noexcept {
  using namespace ltc_detail;
  if (count < 3 || count > kLtcMaxVertices) return 0;
  V3 v[kLtcMaxVertices];
  for (int i = 0; i < count; ++i) {
    V3 q{p[i][0], p[i][1], p[i][2]};
    v[i] = unit(V3{minv[0] * q.x + minv[1] * q.y + minv[2] * q.z,
                   minv[3] * q.x + minv[4] * q.y + minv[5] * q.z,
                   minv[6] * q.x + minv[7] * q.y + minv[8] * q.z});
  }
  // Sutherland-Hodgman against z >= 0 (a polygon of n vertices keeps at most n + 1).
  V3 c[kLtcMaxVertices + 1];
  int n = 0;
  for (int i = 0; i < count; ++i) {
    V3 a = v[i], b = v[(i + 1) % count];
    bool ina = a.z >= 0, inb = b.z >= 0;
    if (ina) c[n++] = a;
    if (ina != inb && n < kLtcMaxVertices + 1) {
      double t = a.z / (a.z - b.z);
      V3 h{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0};
      c[n++] = unit(h);
    }
  }
  if (n < 3) return 0;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += edgeZ(c[i], c[(i + 1) % n]);
  double e = sum / (2 * 3.14159265358979323846);
  if (twoSided) return std::fabs(e);
  return e > 0 ? e : 0;
}

/// M^-1 of a texel in the shading frame of normal `n` and view `v` (world space, unit, n.v > 0):
/// the stored inverse times the world-to-shading rotation, so that ltcPolygonIntegral takes
/// world-space vertices relative to the shaded point. Where v is along n the frame's x is any
/// unit vector orthogonal to n (the lobe is then rotationally symmetric).
inline void ltcWorldInverse(const LtcInverse& t, const double n[3], const double v[3],
                            double out[9]) noexcept {
  using namespace ltc_detail;
  V3 N{n[0], n[1], n[2]}, V{v[0], v[1], v[2]};
  V3 T1 = sub(V, scale(N, dot(N, V)));
  if (dot(T1, T1) < 1e-24)
    T1 = std::fabs(N.x) < 0.9 ? cross(N, V3{1, 0, 0}) : cross(N, V3{0, 1, 0});
  T1 = unit(T1);
  V3 T2 = cross(N, T1);
  const double m[9] = {t.a, 0, t.c, 0, 1, 0, t.b, 0, t.d};
  const V3 rows[3] = {T1, T2, N};  // world -> shading
  for (int i = 0; i < 3; ++i) {
    V3 r{m[3 * i + 0] * rows[0].x + m[3 * i + 1] * rows[1].x + m[3 * i + 2] * rows[2].x,
         m[3 * i + 0] * rows[0].y + m[3 * i + 1] * rows[1].y + m[3 * i + 2] * rows[2].y,
         m[3 * i + 0] * rows[0].z + m[3 * i + 1] * rows[1].z + m[3 * i + 2] * rows[2].z};
    out[3 * i + 0] = r.x;
    out[3 * i + 1] = r.y;
    out[3 * i + 2] = r.z;
  }
}

/// The stored coefficients as a row-major M^-1 in the shading frame (no rotation).
inline void ltcLocalInverse(const LtcInverse& t, double out[9]) noexcept {
  const double m[9] = {t.a, 0, t.c, 0, 1, 0, t.b, 0, t.d};
  for (int i = 0; i < 9; ++i) out[i] = m[i];
}

}  // namespace kiln

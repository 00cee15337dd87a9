// kiln_lut.hlsl: sample kiln lookup tables on the GPU (HLSL, Shader Model 4.0 and later).
//
// Paste or #include this into a shader. The texture is the table's EXR image
// uploaded as is (width size0, height size1 * size2, row 0 = EXR row 0 at
// v = 0), channels in kiln.channels order as R, G, B, A, as a float texture
// (R32_FLOAT/R32G32_FLOAT/R32G32B32A32_FLOAT, or 16_FLOAT for half tables),
// sampled with a SamplerState of
//     Filter = MIN_MAG_MIP_LINEAR, AddressU = AddressV = CLAMP, and no mipmaps.
// The KilnAxis values come from the file's kiln.axis<i>.* attributes (or the
// constants of a header written by `kiln`); pass them in a constant buffer.
//
// Mapping (the same as kiln::Axis::gpuCoord in kiln/lut.h):
//     t = warp((x - lo) / (hi - lo))   (log: t = ln(x / lo) / ln(hi / lo)), x clamped to [lo, hi]
//                                      (root4-layer: also of c = max(x1^2, 1e-12), c = 0 at x1 = 0;
//                                       root4-layer-angle: the same after y -> (2/pi) asin(y);
//                                       layer-eta: of c = sqrt(|x1^2 - 1|), c = 0 at x1 = 1;
//                                       root4-layer-split(2): also of axis 2's value x2,
//                                       kilnSplitAt; a 2D table's constant split: kiln.axis0.split;
//                                       x1 axis 1's value, kilnLayerScale)
//     s = t * (size - 1)               continuous node index
//     u = (0.5 + s) / size             texture coordinate: node i sits on texel centre i
//
// Precision: every value here is `float` (32-bit). Keep it so: `half` or
// `min16float` coordinates (fp16) flush the layer scale's floor 1e-12 to 0 and
// make the coordinate at mu = 0, roughness 0 a NaN (0/0).
//
// Hardware bilinear filtering quantizes the blend weights (8 bits
// of fraction on common GPUs), which can add an error of about 1/512 of the
// step between neighbouring texels. The *Exact variants blend Load()ed texels
// in full float precision, matching the CPU runtime.

#ifndef KILN_LUT_HLSL
#define KILN_LUT_HLSL

#define KILN_WARP_LINEAR 0
#define KILN_WARP_SQRT 1
#define KILN_WARP_SQUARE 2
#define KILN_WARP_LOG 3
#define KILN_WARP_ROOT4 4
#define KILN_WARP_ROOT4_LAYER 5  // axis 0 only: follows the value of axis 1 (kiln/lut.h)
#define KILN_WARP_ANGLE 6
#define KILN_WARP_LAYER_ETA 7  // axis 0 only: follows the index of axis 1 (kiln/lut.h)
#define KILN_WARP_ROOT4_LAYER_SPLIT 8  // axis 0 only: split at a point (kiln/lut.h, kilnSplitAt)
#define KILN_WARP_ROOT4_LAYER_ANGLE 9  // axis 0 only: root4-layer after u = (2/pi) asin(y)
#define KILN_WARP_ROOT4_LAYER_SPLIT2 10  // axis 0 of a 3D table: split at two points of axis 2's eta
#define KILN_WARP_ARCSINE 11

struct KilnAxis {
    float lo;    // kiln.axis<i>.lo
    float hi;    // kiln.axis<i>.hi
    float size;  // kiln.axis<i>.size, number of nodes
    int warp;    // KILN_WARP_* from kiln.axis<i>.warp
};

// Layer scale of a root4-layer axis 0, r the value of axis 1 clamped to that
// axis: c = max(r^2, 1e-12) for r > 0, and c = 0 at r = 0 exactly (the smooth limit).
float kilnLayerScale(float r, KilnAxis a1) {
    float rc = clamp(r, a1.lo, a1.hi);
    return rc > 0.0 ? max(rc * rc, 1e-12) : 0.0;
}

// Layer scale of axis 0 (a0) at the value x1 of axis 1 (a1): kilnLayerScale for
// root4-layer; c = max(sqrt(|x1^2 - 1|), 1e-12), 0 at x1 = 1 exactly, for
// layer-eta; ignored (1e-12) for the other warps.
float kilnLayerScale(float x1, KilnAxis a0, KilnAxis a1) {
    if (a0.warp == KILN_WARP_ROOT4_LAYER || a0.warp == KILN_WARP_ROOT4_LAYER_ANGLE ||
        a0.warp == KILN_WARP_ROOT4_LAYER_SPLIT || a0.warp == KILN_WARP_ROOT4_LAYER_SPLIT2)
        return kilnLayerScale(x1, a1);
    if (a0.warp != KILN_WARP_LAYER_ETA) return 1e-12;
    float ec = clamp(x1, a1.lo, a1.hi);
    float c = sqrt(abs((ec - 1.0) * (ec + 1.0)));
    return c > 0.0 ? max(c, 1e-12) : 0.0;
}

// The root4-layer warp of y in [0, 1] at layer scale c, collapsed at c = 0 (kiln::Axis::
// layerWarpCollapsible): (y^(1/4) + y (1 + c) / (y + c)) / 2; (y^(1/4) + 1) / 2 at c = 0.
float kilnLayerWarp(float y, float c) {
    if (!(y > 0.0)) return c == 0.0 ? 0.5 : 0.0;
    if (!(y < 1.0)) return 1.0;
    if (c == 0.0) return 0.5 * (sqrt(sqrt(y)) + 1.0);
    return 0.5 * (sqrt(sqrt(y)) + y * (1.0 + c) / (y + c));
}

// The split argument of kilnWarped for axis 0 (a0) of a 3D table at the value x2 of axis 2
// (a2), as kiln::LutView::splitAt: root4-layer-split, the critical cosine sqrt(1 - eta^2) of
// x2 clamped to a2 (0 for eta >= 1), clamped into [lo + (hi - lo) / 64, hi - (hi - lo) / 64];
// root4-layer-split2, x2 clamped to a2; 0.5 (ignored) for the other warps. (A 2D table with a
// constant split, kiln.axis0.split, passes that value to kilnSample2D instead.)
float kilnSplitAt(float x2, KilnAxis a0, KilnAxis a2) {
    float ec = clamp(x2, a2.lo, a2.hi);
    if (a0.warp == KILN_WARP_ROOT4_LAYER_SPLIT2) return ec;
    if (a0.warp != KILN_WARP_ROOT4_LAYER_SPLIT) return 0.5;
    float q = (1.0 - ec) * (1.0 + ec);
    float s = q > 0.0 ? sqrt(q) : 0.0;
    return clamp(s, a0.lo + (a0.hi - a0.lo) / 64.0, a0.hi - (a0.hi - a0.lo) / 64.0);
}

// Warped coordinate t in [0, 1] of x; x is clamped to [lo, hi]. c: the layer
// scale of a root4-layer axis (kilnLayerScale), ignored by the other warps;
// split: kilnSplitAt's value for a root4-layer-split(2) axis, ignored by the others.
float kilnWarped(float x, KilnAxis a, float c, float split) {
    float xc = clamp(x, a.lo, a.hi);
    if (a.warp == KILN_WARP_LOG) return saturate(log(xc / a.lo) / log(a.hi / a.lo));
    float y = (xc - a.lo) / (a.hi - a.lo);
    if (a.warp == KILN_WARP_SQRT) return sqrt(y);
    if (a.warp == KILN_WARP_SQUARE) return y * y;
    if (a.warp == KILN_WARP_ROOT4) return sqrt(sqrt(y));
    if (a.warp == KILN_WARP_ANGLE) return 1.0 - acos(y) * 0.63661977236758134;  // 2 / pi
    if (a.warp == KILN_WARP_ARCSINE) return asin(sqrt(y)) * 0.63661977236758134;
    if (a.warp == KILN_WARP_ROOT4_LAYER_SPLIT) {
        // Three root4-layer pieces: [0, m] (t to 1/4), [m, ys] (to 1/2), [ys, 1] (to 1), m = ys / 2.
        float ys = (split - a.lo) / (a.hi - a.lo), m = 0.5 * ys;
        if (y <= m) return 0.25 * kilnLayerWarp(y / m, c / m);
        if (y <= ys) return 0.5 - 0.25 * kilnLayerWarp((ys - y) / m, c / m);
        return min(0.5 + 0.5 * kilnLayerWarp((y - ys) / (1.0 - ys), c / (1.0 - ys)), 1.0);
    }
    if (a.warp == KILN_WARP_ROOT4_LAYER_SPLIT2) {
        // Five root4-layer pieces between the lines 5/16, 8/16, 10/16, 13/16 of t, at the breaks
        // pa <= pb (the critical cosine and eta, in y; split is eta): kiln::Axis::split2Breaks.
        float q = (1.0 - split) * (1.0 + split);
        float xcr = q > 0.0 ? sqrt(q) : 0.0;
        float lo64 = a.lo + (a.hi - a.lo) / 64.0, hi64 = a.hi - (a.hi - a.lo) / 64.0;
        float yc = (clamp(xcr, lo64, hi64) - a.lo) / (a.hi - a.lo);
        float ye = (clamp(split, lo64, hi64) - a.lo) / (a.hi - a.lo);
        float pa = min(yc, ye), pb = max(yc, ye);
        float m = 0.5 * pa, w = 0.5 * (pb - pa);
        float cw = w > 0.0 && c / w < 1e12 ? c / w : (c > 0.0 ? 1e12 : 0.0);
        if (y <= m) return 0.3125 * kilnLayerWarp(y / m, c / m);
        if (y <= pa) return 0.5 - 0.1875 * kilnLayerWarp((pa - y) / m, c / m);
        if (y <= pa + w && w > 0.0) return 0.5 + 0.125 * kilnLayerWarp((y - pa) / w, cw);
        if (y <= pb && w > 0.0) return 0.8125 - 0.1875 * kilnLayerWarp((pb - y) / w, cw);
        return min(0.8125 + 0.1875 * kilnLayerWarp((y - pb) / (1.0 - pb), c / (1.0 - pb)), 1.0);
    }
    if (a.warp == KILN_WARP_ROOT4_LAYER_ANGLE) {
        y = asin(y) * 0.63661977236758134;  // u = (2 / pi) asin(y), then root4-layer
        if (c > 0.0) return 0.5 * (sqrt(sqrt(y)) + y * (1.0 + c) / (y + c));
        return 0.5 * (sqrt(sqrt(y)) + 1.0);
    }
    if (a.warp == KILN_WARP_ROOT4_LAYER) {
        if (c > 0.0) return 0.5 * (sqrt(sqrt(y)) + y * (1.0 + c) / (y + c));
        return 0.5 * (sqrt(sqrt(y)) + 1.0);  // collapsed (r = 0): the outer half
    }
    if (a.warp == KILN_WARP_LAYER_ETA) {
        if (c > 0.0) return y * (1.0 + c) / (y + c);
        return y > 0.0 ? 1.0 : 0.0;  // collapsed (eta = 1)
    }
    return y;
}

float kilnWarped(float x, KilnAxis a, float c) {
    return kilnWarped(x, a, c, 0.5);
}

// Continuous node index s = t * (size - 1) of x.
float kilnTexel(float x, KilnAxis a, float c, float split) {
    return kilnWarped(x, a, c, split) * max(a.size - 1.0, 0.0);
}
float kilnTexel(float x, KilnAxis a, float c) {
    return kilnTexel(x, a, c, 0.5);
}
float kilnTexel(float x, KilnAxis a) {
    return kilnTexel(x, a, 1e-12);
}

// Texture coordinate (0.5 + s) / size of x, for hardware bilinear filtering.
float kilnCoord(float x, KilnAxis a, float c, float split) {
    return (0.5 + kilnTexel(x, a, c, split)) / a.size;
}
float kilnCoord(float x, KilnAxis a, float c) {
    return kilnCoord(x, a, c, 0.5);
}
float kilnCoord(float x, KilnAxis a) {
    return kilnCoord(x, a, 1e-12);
}

// 1D table (size0 x 1 image) at x.
float4 kilnSample1D(Texture2D<float4> lut, SamplerState linearClamp, float x, KilnAxis a0) {
    return lut.SampleLevel(linearClamp, float2(kilnCoord(x, a0), 0.5), 0.0);
}

// 2D table at x = (x0, x1): one hardware bilinear fetch.
float4 kilnSample2D(Texture2D<float4> lut, SamplerState linearClamp, float2 x, KilnAxis a0,
                    KilnAxis a1) {
    return lut.SampleLevel(linearClamp, float2(kilnCoord(x.x, a0, kilnLayerScale(x.y, a0, a1)), kilnCoord(x.y, a1)), 0.0);
}

// 2D table whose axis 0 is root4-layer-split with a constant split point (the file's
// kiln.axis0.split): the same fetch, axis 0 split there.
float4 kilnSample2D(Texture2D<float4> lut, SamplerState linearClamp, float2 x, KilnAxis a0,
                    KilnAxis a1, float split) {
    return lut.SampleLevel(linearClamp, float2(kilnCoord(x.x, a0, kilnLayerScale(x.y, a0, a1), split), kilnCoord(x.y, a1)), 0.0);
}

// 3D table (slices along axis 2 stacked vertically) at x = (x0, x1, x2): a
// bilinear fetch in the two slices around x2, blended linearly. The fetch
// never bleeds into the neighbouring slice: its v stays between the centres
// of the slice's first and last rows.
float4 kilnSample3D(Texture2D<float4> lut, SamplerState linearClamp, float3 x, KilnAxis a0,
                    KilnAxis a1, KilnAxis a2) {
    float u = kilnCoord(x.x, a0, kilnLayerScale(x.y, a0, a1), kilnSplitAt(x.z, a0, a2));
    float s1 = kilnTexel(x.y, a1);
    float s2 = kilnTexel(x.z, a2);
    float k0 = min(floor(s2), max(a2.size - 2.0, 0.0));
    float k1 = min(k0 + 1.0, a2.size - 1.0);
    float rows = a1.size * a2.size;
    float4 c0 = lut.SampleLevel(linearClamp, float2(u, (k0 * a1.size + 0.5 + s1) / rows), 0.0);
    float4 c1 = lut.SampleLevel(linearClamp, float2(u, (k1 * a1.size + 0.5 + s1) / rows), 0.0);
    return lerp(c0, c1, s2 - k0);
}

// Bilinear blend in full precision at continuous texel position p (column,
// row), node i at integer i, clamped to the image.
float4 kilnBlendExact(Texture2D<float4> lut, float2 p) {
    uint width, height;
    lut.GetDimensions(width, height);
    int2 last = int2(width, height) - 1;
    float2 base = floor(p);
    float2 f = p - base;
    int2 i0 = clamp(int2(base), int2(0, 0), last);
    int2 i1 = min(i0 + 1, last);
    float4 a = lerp(lut.Load(int3(i0, 0)), lut.Load(int3(i1.x, i0.y, 0)), f.x);
    float4 b = lerp(lut.Load(int3(i0.x, i1.y, 0)), lut.Load(int3(i1, 0)), f.x);
    return lerp(a, b, f.y);
}

// As kilnSample2D, with the blend in full float precision.
float4 kilnSample2DExact(Texture2D<float4> lut, float2 x, KilnAxis a0, KilnAxis a1) {
    return kilnBlendExact(lut, float2(kilnTexel(x.x, a0, kilnLayerScale(x.y, a0, a1)), kilnTexel(x.y, a1)));
}
float4 kilnSample2DExact(Texture2D<float4> lut, float2 x, KilnAxis a0, KilnAxis a1, float split) {
    return kilnBlendExact(lut, float2(kilnTexel(x.x, a0, kilnLayerScale(x.y, a0, a1), split), kilnTexel(x.y, a1)));
}

// As kilnSample3D, with the blends in full float precision.
float4 kilnSample3DExact(Texture2D<float4> lut, float3 x, KilnAxis a0, KilnAxis a1, KilnAxis a2) {
    float s0 = kilnTexel(x.x, a0, kilnLayerScale(x.y, a0, a1), kilnSplitAt(x.z, a0, a2));
    float s1 = kilnTexel(x.y, a1);
    float s2 = kilnTexel(x.z, a2);
    float k0 = min(floor(s2), max(a2.size - 2.0, 0.0));
    float k1 = min(k0 + 1.0, a2.size - 1.0);
    // Clamp the row within the slice so the blend never reaches the next one.
    float r = min(s1, a1.size - 1.0);
    float4 c0 = kilnBlendExact(lut, float2(s0, k0 * a1.size + r));
    float4 c1 = kilnBlendExact(lut, float2(s0, k1 * a1.size + r));
    return lerp(c0, c1, s2 - k0);
}

// The exact dielectric Fresnel reflectance (unpolarized) at cos(theta_i) = mu (clamped to
// [0, 1]) and relative index eta >= 1, cancellation-free (kiln::dielectricFresnel).
float kilnFresnelDielectric(float mu, float eta) {
    float m = clamp(mu, 0.0, 1.0);
    float e = (eta - 1.0) * (eta + 1.0);
    float cos2t = (m * m + e) / (eta * eta);
    if (cos2t <= 0.0) return 1.0;
    float cost = sqrt(cos2t);
    float a = m + eta * cost;
    float b = eta * m + cost;
    float rPerp = -e / (a * a);
    float rParl = e * ((eta * eta + 1.0) * m * m - 1.0) / (eta * eta * b * b);
    return min(1.0, 0.5 * (rParl * rParl + rPerp * rPerp));
}

// The closed form g a ggx-fresnel-albedo file with channel E_residual stores E against
// (kiln::fresnelAlbedoClosedForm, runtime/FORMAT.md "Stored forms"): E = sample + g at the
// view cosine mu, perceptual roughness r and index eta of the lookup (clamped to the axes).
float kilnFresnelAlbedoClosedForm(float mu, float r, float eta) {
    float m = clamp(mu, 0.0, 1.0);
    float rc = clamp(r, 0.0, 1.0);
    if (!(rc > 0.0)) return kilnFresnelDielectric(m, eta);
    float alpha = max(rc * rc, 1e-12);
    float s = m / alpha;
    float h = 1.0 - 0.211 * s / (1.0 + s * (0.4 + s * (0.3 + 0.25 * s)));
    return kilnFresnelDielectric(sqrt(m * m + alpha * alpha), eta) * h / (1.0 + 10.0 * alpha);
}

// The dielectric Fresnel reflectance with the transmitted cosine softened by delta >= 0
// (kiln::dielectricFresnelSoft): w = Re sqrt(q + i delta), q = mu^2 + eta^2 - 1, for any
// eta > 0; delta = 0 is the exact term (1 under total internal reflection).
float kilnFresnelDielectricSoft(float mu, float eta, float delta) {
    float m = clamp(mu, 0.0, 1.0);
    if (!(delta > 0.0)) return kilnFresnelDielectric(m, eta);
    float q = m * m + (eta - 1.0) * (eta + 1.0);
    float root = sqrt(q * q + delta * delta);
    float w = sqrt(0.5 * (q >= 0.0 ? q + root : delta * delta / (root - q)));
    if (!(m + w > 0.0)) return 1.0;
    float rs = (m - w) / (m + w);
    float rp = (eta * eta * m - w) / (eta * eta * m + w);
    return min(1.0, 0.5 * (rs * rs + rp * rp));
}

// The closed form g a ggx-dielectric-albedo-* file with channel E_R_residual (transmit false)
// or E_T_residual (transmit true) stores E against (kiln::dielectricAlbedoClosedForm,
// runtime/FORMAT.md "Stored forms"): E = sample + g at the view cosine mu, perceptual roughness r
// and index eta (> 1 entering, < 1 exit) of the lookup (clamped to the axes).
float kilnDielectricAlbedoClosedForm(float mu, float r, float eta, bool transmit) {
    float m = clamp(mu, 0.0, 1.0);
    float rc = clamp(r, 0.0, 1.0);
    if (!(rc > 0.0)) {
        float f0 = kilnFresnelDielectricSoft(m, eta, 0.0);
        return transmit ? 1.0 - f0 : f0;
    }
    float alpha = max(rc * rc, 1e-12);
    // delta = 4 alpha mu_s at the cosine mu_s = sqrt(mu^2 + alpha^2) F_s is taken at (eta < 1).
    float muS = sqrt(m * m + alpha * alpha);
    float delta = eta < 1.0 ? 4.0 * alpha * muS : 0.0;
    float f = kilnFresnelDielectricSoft(muS, eta, delta);
    if (transmit) return 1.0 - f;
    float s = m / alpha;
    float h = 1.0 - 0.211 * s / (1.0 + s * (0.4 + s * (0.3 + 0.25 * s)));
    return f * h / (1.0 + 20.0 * alpha);
}

// v of a GGX slope x = tan(beta) along the view's azimuth: x / sqrt(alpha^2 + x^2), beta in
// (-pi/2, pi/2] (the slope's cumulative coordinate of kilnDielectricExitClosedForm).
float kilnExitSlopeV(float beta, float alpha) {
    float s = sin(beta), c = cos(beta);
    return s / sqrt(alpha * alpha * c * c + s * s);
}

// 12-node Gauss-Legendre on [0, 1], the first half (the rest mirrored: 1 - x, same weight),
// as kiln/stored.h dielectricExitClosedForm.
static const float kKilnGaussX[6] = {0.0092196828766403782, 0.047941371814762601,
    0.11504866290284765, 0.20634102285669126, 0.31608425050090994, 0.43738329574426554};
static const float kKilnGaussW[6] = {0.023587668193255917, 0.053469662997659088,
    0.080039164271673166, 0.10158371336153292, 0.11674626826917739, 0.12457352290670144};

// The slope average's integrand at u in [0, 1] (phi = pi u, v from v1 to v2 as (1 - cos phi) / 2).
float kilnExitSlopeTerm(float u, float v1, float v2, float alpha,
                              float thetaO, float eta) {
    float phi = 3.14159265358979 * u;
    float v = v1 + (v2 - v1) * 0.5 * (1.0 - cos(phi));
    float dv = (v2 - v1) * 0.5 * sin(phi) * 3.14159265358979;
    if (!(dv > 0.0)) return 0.0;
    float vc = clamp(v, -1.0, 1.0);
    float x = alpha * vc / sqrt(max((1.0 - vc) * (1.0 + vc), 1e-30));
    return kilnFresnelDielectric(max(cos(thetaO - atan(x)), 0.0), eta) * dv;
}

// The closed form g a ggx-dielectric-albedo-r-exit / -t-exit file with channel E_R_tir_residual
// (transmit false) or E_T_tir_residual (transmit true) stores E against
// (kiln::dielectricExitClosedForm, runtime/FORMAT.md "Stored forms"): the smooth interface's F
// averaged over GGX's slopes along the view's azimuth (f; g_T = 1 - f), and for E_R the grazing
// terms f h(s) - K(eta) alpha^2 s ln(1 + 1/s) / (1 + s), s = mu / alpha. E = sample + g at the
// view cosine mu, perceptual roughness r and index eta (< 1: the view inside the denser medium)
// of the lookup (clamped to the axes). About 24 Fresnel evaluations.
float kilnDielectricExitClosedForm(float mu, float r, float eta, bool transmit) {
    float m = clamp(mu, 0.0, 1.0);
    float rc = clamp(r, 0.0, 1.0);
    if (!(rc > 0.0)) {
        float f0 = kilnFresnelDielectric(m, eta);
        return transmit ? 1.0 - f0 : f0;
    }
    float alpha = max(rc * rc, 1e-12);
    float halfPi = 1.57079632679490;
    float thetaO = acos(m);
    float v1 = -1.0, v2 = 1.0;
    float thetaC = halfPi;  // psi's end for K: all of [0, pi/2] for eta >= 1
    if (eta < 1.0) {
        thetaC = acos(sqrt((1.0 - eta) * (1.0 + eta)));
        v1 = kilnExitSlopeV(thetaO - thetaC, alpha);
        if (thetaO + thetaC < halfPi) v2 = kilnExitSlopeV(thetaO + thetaC, alpha);
    }
    float inside = 0.0;
    for (int k = 0; k < 6; ++k)
        inside += kKilnGaussW[k] * (kilnExitSlopeTerm(kKilnGaussX[k], v1, v2, alpha, thetaO, eta) +
                                    kilnExitSlopeTerm(1.0 - kKilnGaussX[k], v1, v2, alpha, thetaO, eta));
    float f = min(1.0, 0.5 * ((v1 + 1.0) + (1.0 - v2) + inside));
    if (transmit) return 1.0 - f;
    // K = (2 / pi) int_0^(pi/2) F(cos psi) dpsi: F = 1 beyond theta_c; the rule on [0, theta_c]
    // in psi = theta_c (1 - cos phi) / 2.
    float kSum = 0.0;
    for (int i = 0; i < 6; ++i) {
        float pa = 3.14159265358979 * kKilnGaussX[i], pb = 3.14159265358979 * (1.0 - kKilnGaussX[i]);
        kSum += kKilnGaussW[i] * (kilnFresnelDielectric(cos(thetaC * 0.5 * (1.0 - cos(pa))), eta) * sin(pa) +
                                  kilnFresnelDielectric(cos(thetaC * 0.5 * (1.0 - cos(pb))), eta) * sin(pb));
    }
    float kEta = (kSum * thetaC * 0.5 * 3.14159265358979 + (halfPi - thetaC)) * 0.63661977236758134;
    float s = m / alpha;
    float h = 1.0 - 0.211 * s / (1.0 + s * (0.4 + s * (0.3 + 0.25 * s)));
    float layer = s > 0.0 ? s * log(1.0 + 1.0 / s) / (1.0 + s) : 0.0;
    return f * h - kEta * alpha * alpha * layer;
}

// The closed form a ggx-dielectric-btdf-split-sum file's channel T_F_residual stores T_F against
// (kiln::btdfFresnelClosedForm): F(sqrt(mu^2 + alpha^2), eta), alpha = r^2, eta >= 1.
float kilnBtdfFresnelClosedForm(float mu, float r, float eta) {
    return 1.0 - kilnDielectricAlbedoClosedForm(mu, r, eta, true);
}

// The split-sum BTDF pair's weight for image-based refraction (ggx-dielectric-btdf-split-sum,
// axes (mu, roughness, eta = ior >= 1.1) from kiln.axis0..2): the energy the rough interface
// transmits, T_lobe - s T_F, s the scale of the Fresnel term (1: the model; KHR_materials_specular's
// specular factor). Multiply the prefiltered environment sampled along the refracted ray by it
// (importance form: divide by eta^2 for radiance).
float kilnBtdfSplitSum(Texture2D<float4> lut, SamplerState smp, float NoV, float r, float eta,
                       float s, KilnAxis a0, KilnAxis a1, KilnAxis a2) {
    float2 t = kilnSample3D(lut, smp, float3(NoV, r, eta), a0, a1, a2).rg;
    float tF = t.y + kilnBtdfFresnelClosedForm(NoV, r, eta);
    return t.x - s * tF;
}

#endif  // KILN_LUT_HLSL

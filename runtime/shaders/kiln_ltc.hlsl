// kiln_ltc.hlsl: polygonal area lights through kiln's LTC tables (kind `ltc`; Heitz, Dupuy,
// Hill & Neubelt 2016). Shader Model 5 and later; the same maths as kiln::ltcPolygonIntegral
// (kiln/ltc.h) and kiln_ltc.glsl. Textures as in kiln_ltc.glsl: channels 0-3 of the table as
// `ltc1` (RGBA), 4-5 as `ltc2` (RG), linear filtering, clamp addressing.

#ifndef KILN_LTC_HLSL
#define KILN_LTC_HLSL

// Texture coordinate of (perceptual roughness, N.V) on a size x size LTC table.
float2 kilnLtcUv(float roughness, float NoV, float size) {
    float2 t = float2(saturate(roughness), sqrt(1.0 - saturate(NoV)));
    return (t * (size - 1.0) + 0.5) / size;
}

// M^-1 in world space from t1 = (a, b, c, d), unit normal N and unit view V (see the GLSL).
float3x3 kilnLtcInverse(float4 t1, float3 N, float3 V) {
    float3x3 m = float3x3(t1.x, 0.0, t1.z, 0.0, 1.0, 0.0, t1.y, 0.0, t1.w);
    float3 T1 = V - N * dot(V, N);
    T1 = dot(T1, T1) > 1e-12 ? normalize(T1)
                             : normalize(cross(N, abs(N.x) < 0.9 ? float3(1, 0, 0) : float3(0, 1, 0)));
    float3 T2 = cross(N, T1);
    return mul(m, float3x3(T1, T2, N));
}

float kilnLtcEdge(float3 v1, float3 v2) {
    float3 c = cross(v1, v2);
    float s = length(c);
    return s > 0.0 ? atan2(s, dot(v1, v2)) * c.z / s : 0.0;
}

// Integral of the LTC over the quad p0..p3 (world space, relative to the shaded point).
float kilnLtcQuad(float3x3 minv, float3 p0, float3 p1, float3 p2, float3 p3, bool twoSided) {
    float3 v[4];
    v[0] = normalize(mul(minv, p0));
    v[1] = normalize(mul(minv, p1));
    v[2] = normalize(mul(minv, p2));
    v[3] = normalize(mul(minv, p3));
    float3 c[5];
    int n = 0;
    [unroll] for (int i = 0; i < 4; ++i) {
        float3 a = v[i];
        float3 b = v[(i + 1) % 4];
        bool ina = a.z >= 0.0;
        bool inb = b.z >= 0.0;
        if (ina) { c[n] = a; n++; }
        if (ina != inb) {
            float t = a.z / (a.z - b.z);
            c[n] = normalize(float3(lerp(a.xy, b.xy, t), 0.0));
            n++;
        }
    }
    if (n < 3) return 0.0;
    float sum = 0.0;
    [unroll] for (int k = 0; k < 5; ++k) {
        if (k < n) sum += kilnLtcEdge(c[k], c[(k + 1) % n]);
    }
    float e = sum / 6.28318530717958648;
    return twoSided ? abs(e) : max(e, 0.0);
}

#endif  // KILN_LTC_HLSL

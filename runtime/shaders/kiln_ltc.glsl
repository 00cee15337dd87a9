// kiln_ltc.glsl: polygonal area lights through kiln's LTC tables (kind `ltc`; Heitz, Dupuy,
// Hill & Neubelt 2016, "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines").
// GLSL 3.30 / ES 3.00 and later; the same maths as kiln::ltcPolygonIntegral (kiln/ltc.h).
//
// Textures (runtime/FORMAT.md "LTC tables"): the table's channels 0-3 (minv_a, minv_b, minv_c,
// minv_d) as an RGBA float texture `ltc1`, channels 4-5 (norm, fresnel) as an RG(BA) texture
// `ltc2`, both 64 x 64 in the published layout (roughness across, sqrt(1 - N.V) down, row 0 at
// v = 0), GL_LINEAR, GL_CLAMP_TO_EDGE: the layout of the original ltc_1 / ltc_2 textures, so
// a shader written for those reads them unchanged.

#ifndef KILN_LTC_GLSL
#define KILN_LTC_GLSL

// Texture coordinate of (perceptual roughness, N.V) on a size x size LTC table: node i of each
// axis (value i / (size - 1)) sits on texel centre i.
highp vec2 kilnLtcUv(highp float roughness, highp float NoV, highp float size) {
    highp vec2 t = vec2(clamp(roughness, 0.0, 1.0), sqrt(1.0 - clamp(NoV, 0.0, 1.0)));
    return (t * (size - 1.0) + 0.5) / size;
}

// M^-1 in world space from the stored coefficients t1 = (a, b, c, d), the unit normal N and the
// unit view V (pointing away from the surface): [[a, 0, c], [0, 1, 0], [b, 0, d]] times the
// rotation into the shading frame (x = normalize(V - N (N.V)), y = N x x, z = N).
highp mat3 kilnLtcInverse(highp vec4 t1, highp vec3 N, highp vec3 V) {
    highp mat3 m = mat3(vec3(t1.x, 0.0, t1.y), vec3(0.0, 1.0, 0.0), vec3(t1.z, 0.0, t1.w));
    highp vec3 T1 = V - N * dot(V, N);
    T1 = dot(T1, T1) > 1e-12 ? normalize(T1)
                             : normalize(cross(N, abs(N.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
    highp vec3 T2 = cross(N, T1);
    return m * transpose(mat3(T1, T2, N));
}

// theta n.z of the arc from unit v1 to unit v2 (n the unit normal of their great circle).
highp float kilnLtcEdge(highp vec3 v1, highp vec3 v2) {
    highp vec3 c = cross(v1, v2);
    highp float s = length(c);
    return s > 0.0 ? atan(s, dot(v1, v2)) * c.z / s : 0.0;
}

// Integral of the LTC over the quad p0..p3 (world space, relative to the shaded point; counter-
// clockwise seen from it counts positive), clipped to the cosine's upper hemisphere; the
// absolute value when twoSided. Multiply by the light's radiance and by
// F0 * norm + (1 - F0) * fresnel (Schlick, F90 = 1) from ltc2.
highp float kilnLtcQuad(highp mat3 minv, highp vec3 p0, highp vec3 p1, highp vec3 p2,
                        highp vec3 p3, bool twoSided) {
    highp vec3 v[4];
    v[0] = normalize(minv * p0);
    v[1] = normalize(minv * p1);
    v[2] = normalize(minv * p2);
    v[3] = normalize(minv * p3);
    highp vec3 c[5];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        highp vec3 a = v[i];
        highp vec3 b = v[(i + 1) % 4];
        bool ina = a.z >= 0.0;
        bool inb = b.z >= 0.0;
        if (ina) { c[n] = a; n++; }
        if (ina != inb) {
            highp float t = a.z / (a.z - b.z);
            c[n] = normalize(vec3(mix(a.xy, b.xy, t), 0.0));
            n++;
        }
    }
    if (n < 3) return 0.0;
    highp float sum = 0.0;
    for (int i = 0; i < 5; ++i) {
        if (i >= n) break;
        sum += kilnLtcEdge(c[i], c[(i + 1) % n]);
    }
    highp float e = sum / 6.28318530717958648;
    return twoSided ? abs(e) : max(e, 0.0);
}

#endif  // KILN_LTC_GLSL

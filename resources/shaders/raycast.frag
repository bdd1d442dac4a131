#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry pass, volume depth source: the first hit of each pixel's ray with
// the iso-surface of a 3-D texture, into the same G-buffer outputs as
// gbuffer.frag (linear depth, view-space normal with w = 0, object id,
// parameter NaN) and gl_FragDepth, so meshes and the volume depth-test
// together. Rays march in voxel index space (voxel centres at integers).

in vec2 vUv;

uniform sampler3D uVolume;
uniform mat4 uInverseProjection;  // clip -> view
uniform mat4 uProjection;         // view -> clip
uniform mat4 uViewToIndex;        // view -> continuous voxel index
uniform mat4 uIndexToView;
uniform mat3 uNormalMatrix;  // inverse transpose of index -> view (gradients)
uniform vec3 uDims;          // voxels per axis
uniform float uIso;          // in texel units
uniform uint uObjectId;

layout(location = 0) out float fragLinearDepth;
layout(location = 1) out vec4 fragNormal;
layout(location = 2) out uint fragObjectId;
layout(location = 3) out float fragParameter;

const int kMaxSteps = 8192;

// Explicit LOD: the samples sit in non-uniform control flow (no derivatives).
float sampleAt(vec3 p) {
    return textureLod(uVolume, (p + 0.5) / uDims, 0.0).r;
}

void main() {
    vec2 ndc = vUv * 2.0 - 1.0;
    vec4 nearView = uInverseProjection * vec4(ndc, -1.0, 1.0);
    vec4 farView = uInverseProjection * vec4(ndc, 1.0, 1.0);
    vec3 o = (uViewToIndex * vec4(nearView.xyz / nearView.w, 1.0)).xyz;
    vec3 e = (uViewToIndex * vec4(farView.xyz / farView.w, 1.0)).xyz;
    vec3 d = e - o;  // t in [0, 1] runs from the near to the far plane

    // Slab test against the box of the voxel centres.
    vec3 lo = vec3(0.0);
    vec3 hi = uDims - 1.0;
    // Axis-parallel rays: a tiny component instead of 0 keeps the slab test finite.
    vec3 safeD = mix(d, vec3(1e-30), lessThan(abs(d), vec3(1e-30)));
    vec3 inv = 1.0 / safeD;
    vec3 t0 = (lo - o) * inv;
    vec3 t1 = (hi - o) * inv;
    vec3 tmin = min(t0, t1);
    vec3 tmax = max(t0, t1);
    float tEnter = max(max(max(tmin.x, tmin.y), tmin.z), 0.0);
    float tExit = min(min(min(tmax.x, tmax.y), tmax.z), 1.0);
    if (!(tEnter <= tExit)) {
        discard;
    }
    float dt = 0.5 / max(length(d), 1e-12);  // half a voxel per step
    int steps = min(int(ceil((tExit - tEnter) / dt)), kMaxSteps);
    float tPrev = tEnter;
    float t = tEnter;
    bool hit = sampleAt(o + t * d) >= uIso;
    for (int i = 1; i <= steps && !hit; ++i) {
        tPrev = t;
        t = min(tEnter + float(i) * dt, tExit);
        hit = sampleAt(o + t * d) >= uIso;
    }
    if (!hit) {
        discard;
    }
    // Bisection between the last sample below and the first at or above.
    if (t > tPrev) {
        float a = tPrev;
        float b = t;
        for (int i = 0; i < 8; ++i) {
            float m = 0.5 * (a + b);
            if (sampleAt(o + m * d) >= uIso) {
                b = m;
            } else {
                a = m;
            }
        }
        t = b;
    }
    vec3 p = o + t * d;
    vec3 g = vec3(sampleAt(p + vec3(1, 0, 0)) - sampleAt(p - vec3(1, 0, 0)),
                  sampleAt(p + vec3(0, 1, 0)) - sampleAt(p - vec3(0, 1, 0)),
                  sampleAt(p + vec3(0, 0, 1)) - sampleAt(p - vec3(0, 0, 1)));
    vec3 pv = (uIndexToView * vec4(p, 1.0)).xyz;
    // The surface normal points down the gradient (out of the bright inside).
    vec3 n = uNormalMatrix * -g;
    float len = length(n);
    n = len > 0.0 ? n / len : normalize(-pv);
    if (dot(n, -pv) < 0.0) {
        n = -n;
    }
    vec4 clip = uProjection * vec4(pv, 1.0);
    float ndcZ = clip.z / clip.w;
    gl_FragDepth = clamp(ndcZ * 0.5 + 0.5, 0.0, 1.0);
    fragLinearDepth = -pv.z;
    fragNormal = vec4(n, 0.0);
    fragObjectId = uObjectId;
    fragParameter = uintBitsToFloat(0x7fc00000u);
}

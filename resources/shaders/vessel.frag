// SPDX-License-Identifier: GPL-3.0-or-later
// Deferred vessel shading (after vessel_shading.glsl, which has #version and
// the material): every pixel the geometry pass covered is shaded once from
// the G-buffer, so the triangles are rasterised only once per frame and
// shading and depth can never disagree at silhouettes.

in vec2 vUv;

uniform sampler2D uLinearDepth;  // R32F, linear view depth; +inf = no vessel
uniform sampler2D uNormal;       // RGBA16F, view-space normal, w = 1 where the value is valid
uniform sampler2D uParameter;    // R32F, the array value
uniform usampler2D uObjectId;    // R32UI, 0 = no vessel
// Per object, row = object id: texel 0 = (material colour, uses an array),
// texel 1 = (range min, range max, opacity, 1 = labels). Ids above uObjectCount (e.g.
// a volume) show the material of the uniforms.
uniform sampler2D uObjects;
uniform int uObjectCount;
// View-space position of a pixel: xy = (ndc.xy * uViewScale) * depth, z = -depth
// (perspective: uViewScale = (tan(fovy / 2) * aspect, tan(fovy / 2))).
uniform vec2 uViewScale;
// Off-axis frusta (tiles of a larger image): the NDC shift P[2][0], P[2][1]; else 0.
uniform vec2 uViewOffset;

layout(location = 0) out vec4 fragColor;

Material objectMaterial(uint id) {
    if (int(id) > uObjectCount) {
        return uniformMaterial();
    }
    vec4 a = texelFetch(uObjects, ivec2(0, int(id)), 0);
    vec4 b = texelFetch(uObjects, ivec2(1, int(id)), 0);
    return Material(a.w >= 0.5, a.rgb, b.xy, b.w >= 0.5);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint id = texelFetch(uObjectId, p, 0).r;
    if (id == 0u) {
        fragColor = vec4(0.0);
        return;
    }
    float depth = texelFetch(uLinearDepth, p, 0).r;
    vec4 normal = texelFetch(uNormal, p, 0);
    float value = texelFetch(uParameter, p, 0).r;
    vec2 ndc = vUv * 2.0 - 1.0;
    vec3 positionView = vec3((ndc + uViewOffset) * uViewScale * depth, -depth);
    fragColor = vec4(
        shadeVessel(objectMaterial(id), positionView, normal.xyz, value, normal.w >= 0.5,
                    normal.w - 1.0),
        1.0);
}

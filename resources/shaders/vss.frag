#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// VSS shading (VSS.md, "Shading on the VSS"): the void space surface's
// normalised depth z' through a depth colour scale, N iso-lines of constant
// on-screen width (anti-aliased with the screen-space gradient of z'), and
// Blinn-Phong with the normals of the height field, lit like the vessels.
// Output: the shaded VSS with alpha 1 where a VSS exists, 0 elsewhere.

in vec2 vUv;

uniform sampler2D uHeight;   // R32F: z' on void pixels, z on vessel pixels, < -0.5 = no VSS
uniform sampler1D uScale;    // depth colour scale, near (0) to far (1), sRGB
uniform float uScaleSize;    // texels in uScale
uniform float uDmin;         // depth range of z in scene units
uniform float uDmax;
uniform float uPixelScale;   // scene units per pixel per scene unit of depth: 2 tan(fov/2) / H
uniform int uIsoLines;       // N; 0 = none
uniform float uIsoWidth;     // line width in pixels
uniform float uIsoStrength;  // 0..1
uniform float uLighting;     // 0 = flat colours, 1 = full Blinn-Phong
uniform float uOpacity;      // 0..1, the VSS over the background
uniform vec3 uLightDirection;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;

out vec4 fragColor;

bool hasVss(float h) {
    return h > -0.5;
}

float heightAt(ivec2 p, ivec2 size) {
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) {
        return -1.0;
    }
    return texelFetch(uHeight, p, 0).r;
}

// One derivative of z' per pixel: central where both neighbours have a VSS,
// one-sided where one has, 0 where none has.
float derivative(float minus, float centre, float plus) {
    bool m = hasVss(minus);
    bool p = hasVss(plus);
    if (m && p) {
        return 0.5 * (plus - minus);
    }
    if (p) {
        return plus - centre;
    }
    if (m) {
        return centre - minus;
    }
    return 0.0;
}

void main() {
    ivec2 size = textureSize(uHeight, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = heightAt(p, size);
    if (!hasVss(z)) {
        fragColor = vec4(0.0);
        return;
    }
    vec2 grad = vec2(derivative(heightAt(p - ivec2(1, 0), size), z, heightAt(p + ivec2(1, 0), size)),
                     derivative(heightAt(p - ivec2(0, 1), size), z, heightAt(p + ivec2(0, 1), size)));

    // Colour: texel centres, so z' = 0 hits the first entry and 1 the last.
    float t = clamp(z, 0.0, 1.0);
    vec3 base = texture(uScale, (t * (uScaleSize - 1.0) + 0.5) / uScaleSize).rgb;

    // Lighting: the height field h = depth in scene units over a grid of
    // pixels that are (depth * uPixelScale) scene units wide; x right, y up,
    // depth away from the viewer. Its normal faces the viewer.
    float range = max(uDmax - uDmin, 0.0);
    float depth = uDmin + t * range;
    float pixel = max(depth * uPixelScale, 1e-12);
    vec3 n = normalize(vec3(grad * range / pixel, 1.0));
    vec3 l = uLightDirection;
    vec3 v = vec3(0.0, 0.0, 1.0);
    vec3 hv = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, hv), 0.0), uShininess) : 0.0;
    vec3 lit = base * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular);
    vec3 color = mix(base, min(lit, vec3(1.0)), clamp(uLighting, 0.0, 1.0));

    // Iso-lines at z' = k / N: distance to the nearest level in pixels.
    if (uIsoLines > 0 && uIsoStrength > 0.0) {
        float q = t * float(uIsoLines);
        float bands = min(fract(q), 1.0 - fract(q));
        float perPixel = length(grad) * float(uIsoLines);
        float pixels = bands / max(perPixel, 1e-6);
        float half_ = 0.5 * uIsoWidth;
        float coverage = 1.0 - smoothstep(half_ - 0.5, half_ + 0.5, pixels);
        float luminance = dot(color, vec3(0.2126, 0.7152, 0.0722));
        vec3 ink = luminance > 0.3 ? color * 0.15 : vec3(0.8);
        color = mix(color, ink, coverage * clamp(uIsoStrength, 0.0, 1.0));
    }
    fragColor = vec4(color, clamp(uOpacity, 0.0, 1.0));
}

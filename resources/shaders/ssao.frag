#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Screen-space ambient occlusion over the vessels and the VSS together
// (VSS.md, "Depth anchoring"). The occluding surface is the vessels' linear
// depth where there is a vessel, else the VSS as a surface at depth
// dmin + z' (dmax - dmin). Each pixel samples a disc of uRadius scene units
// on screen (a spiral, rotated per pixel by a 4x4 pattern that the blur
// pass averages out) and counts the samples above its tangent plane,
// weighted by distance. Output: r = occlusion in [0, 1], g = the pixel's
// depth (< 0: no surface) for the depth-aware blur.

in vec2 vUv;

uniform sampler2D uLinearDepth;  // R32F, view depth of vessels, +Inf elsewhere
uniform sampler2D uNormal;       // RGBA16F, view-space vessel normals
uniform sampler2D uHeight;       // R32F, z' of the VSS (< -0.5: none)
uniform bool uUseVss;
uniform float uDmin;             // the VSS's depth range in scene units
uniform float uDmax;
uniform float uPixelScale;       // 2 tan(fov / 2) / H
uniform vec2 uAxisOffset;        // the view axis's pixel minus the centre (off-axis tiles; else 0)
uniform float uRadius;           // scene units
uniform int uSamples;
uniform int uStep;               // 1, or 2: this target holds every second pixel per axis

out vec4 fragColor;

ivec2 gSize;

// Depth of the surface at p; < 0 where there is none (background, off screen).
float surfaceDepth(ivec2 p, out bool vessel) {
    vessel = false;
    if (p.x < 0 || p.y < 0 || p.x >= gSize.x || p.y >= gSize.y) {
        return -1.0;
    }
    float d = texelFetch(uLinearDepth, p, 0).r;
    if (d < 1e30) {
        vessel = true;
        return d;
    }
    if (uUseVss) {
        float h = texelFetch(uHeight, p, 0).r;
        if (h > -0.5) {
            return uDmin + clamp(h, 0.0, 1.0) * (uDmax - uDmin);
        }
    }
    return -1.0;
}

float vssDepth(ivec2 p) {
    bool vessel;
    float d = surfaceDepth(p, vessel);
    return vessel ? -1.0 : d;
}

vec3 viewPosition(vec2 pixelCentre, float depth) {
    return vec3((pixelCentre - 0.5 * vec2(gSize) - uAxisOffset) * uPixelScale * depth, -depth);
}

// The VSS's normal from its VSS neighbours only (never across a contour):
// per axis the one-sided difference with the smaller depth step.
vec3 vssNormal(ivec2 p, vec3 centre) {
    vec3 dx = vec3(0.0);
    vec3 dy = vec3(0.0);
    float best = 1e30;
    for (int s = -1; s <= 1; s += 2) {
        ivec2 q = p + ivec2(s, 0);
        float d = vssDepth(q);
        if (d > 0.0 && abs(d + centre.z) < best) {
            best = abs(d + centre.z);
            dx = float(s) * (viewPosition(vec2(q) + 0.5, d) - centre);
        }
    }
    best = 1e30;
    for (int s = -1; s <= 1; s += 2) {
        ivec2 q = p + ivec2(0, s);
        float d = vssDepth(q);
        if (d > 0.0 && abs(d + centre.z) < best) {
            best = abs(d + centre.z);
            dy = float(s) * (viewPosition(vec2(q) + 0.5, d) - centre);
        }
    }
    vec3 n = cross(dx, dy);
    if (dot(dx, dx) == 0.0 || dot(dy, dy) == 0.0 || dot(n, n) == 0.0) {
        return vec3(0.0, 0.0, 1.0);
    }
    n = normalize(n);
    return n.z < 0.0 ? -n : n;
}

void main() {
    gSize = textureSize(uLinearDepth, 0);
    ivec2 target = ivec2(gl_FragCoord.xy);
    ivec2 p = target * uStep;  // the frame's pixel
    bool vessel;
    float depth = surfaceDepth(p, vessel);
    if (depth <= 0.0) {
        fragColor = vec4(0.0, -1.0, 0.0, 0.0);
        return;
    }
    vec3 centre = viewPosition(vec2(p) + 0.5, depth);
    vec3 n = vessel ? normalize(texelFetch(uNormal, p, 0).xyz) : vssNormal(p, centre);

    // 4x4 ordered pattern: rotation and radius offset per pixel.
    const float pattern[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0,
                                        1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
    // (per target pixel: the blur averages it over 4x4 of them)
    float k = pattern[(target.y & 3) * 4 + (target.x & 3)] / 16.0;
    float rotation = 6.2831853 * k;
    float pixels = clamp(uRadius / max(depth * uPixelScale, 1e-12), 1.0, 96.0);
    float radius2 = 4.0 * uRadius * uRadius;  // occluders count up to 2 radii away in depth

    float occlusion = 0.0;
    int n_ = max(uSamples, 1);
    for (int i = 0; i < n_; ++i) {
        float t = (float(i) + 0.5 + 0.5 * k) / float(n_);
        float angle = rotation + 2.3999632 * float(i);
        vec2 offset = pixels * t * vec2(cos(angle), sin(angle));
        ivec2 q = p + ivec2(round(offset));
        if (q == p) {
            continue;
        }
        bool sampleVessel;
        float d = surfaceDepth(q, sampleVessel);
        if (d <= 0.0) {
            continue;
        }
        vec3 v = viewPosition(vec2(q) + 0.5, d) - centre;
        float dist2 = dot(v, v);
        float cosine = dot(n, v) * inversesqrt(max(dist2, 1e-12));
        float falloff = max(1.0 - dist2 / radius2, 0.0);
        occlusion += max(cosine - 0.15, 0.0) * falloff;
    }
    occlusion = clamp(2.0 * occlusion / float(n_), 0.0, 1.0);
    fragColor = vec4(occlusion, depth, 0.0, 1.0);
}

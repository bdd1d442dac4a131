#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Fast approximate anti-aliasing of the composited frame (post-process, so
// the G-buffer and the linear depth the VSS solve reads stay one sample per
// pixel). Where the local luma contrast is high, the edge direction is
// estimated from the luma of the four diagonal neighbours and the colour is
// averaged along it (two or four bilinear taps, the wider set only when its
// luma stays within the neighbourhood's range).

in vec2 vUv;

uniform sampler2D uColor;  // the composited frame, sampled with linear filtering
uniform vec2 uTexel;       // 1 / size

out vec4 fragColor;

float luma(vec3 c) {
    return dot(c, vec3(0.299, 0.587, 0.114));
}

vec3 fetch(vec2 uv) {
    return textureLod(uColor, uv, 0.0).rgb;
}

void main() {
    vec2 uv = gl_FragCoord.xy * uTexel;
    vec3 centre = fetch(uv);
    float lM = luma(centre);
    float lNW = luma(textureLodOffset(uColor, uv, 0.0, ivec2(-1, 1)).rgb);
    float lNE = luma(textureLodOffset(uColor, uv, 0.0, ivec2(1, 1)).rgb);
    float lSW = luma(textureLodOffset(uColor, uv, 0.0, ivec2(-1, -1)).rgb);
    float lSE = luma(textureLodOffset(uColor, uv, 0.0, ivec2(1, -1)).rgb);
    float lMin = min(lM, min(min(lNW, lNE), min(lSW, lSE)));
    float lMax = max(lM, max(max(lNW, lNE), max(lSW, lSE)));
    if (lMax - lMin < max(0.04, 0.12 * lMax)) {
        fragColor = vec4(centre, 1.0);
        return;
    }
    // Perpendicular to the luma gradient: along the edge.
    vec2 dir = vec2((lSW + lSE) - (lNW + lNE), (lNW + lSW) - (lNE + lSE));
    float bias = max(0.03125 * (lNW + lNE + lSW + lSE), 1.0 / 128.0);
    dir *= 1.0 / (min(abs(dir.x), abs(dir.y)) + bias);
    dir = clamp(dir, vec2(-6.0), vec2(6.0)) * uTexel;
    vec3 inner = 0.5 * (fetch(uv - dir / 6.0) + fetch(uv + dir / 6.0));
    vec3 outer = 0.5 * inner + 0.25 * (fetch(uv - 0.5 * dir) + fetch(uv + 0.5 * dir));
    float lOuter = luma(outer);
    fragColor = vec4((lOuter < lMin || lOuter > lMax) ? inner : outer, 1.0);
}

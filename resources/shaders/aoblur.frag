#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Depth-aware (bilateral) blur of the SSAO: a 4x4 box, which averages the
// SSAO pass's 4x4 rotation pattern exactly, whose taps count less the more
// their depth differs from the centre's, so that occlusion does not bleed
// across depth edges (vessel over VSS). Output: r = occlusion in [0, 1].

in vec2 vUv;

uniform sampler2D uAo;  // RG32F: occlusion, depth (< 0: no surface)

out vec4 fragColor;

void main() {
    ivec2 size = textureSize(uAo, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 centre = texelFetch(uAo, p, 0).rg;
    if (centre.y <= 0.0) {
        fragColor = vec4(0.0);
        return;
    }
    float sum = 0.0;
    float weights = 0.0;
    for (int y = -2; y <= 1; ++y) {
        for (int x = -2; x <= 1; ++x) {
            ivec2 q = clamp(p + ivec2(x, y), ivec2(0), size - 1);
            vec2 s = texelFetch(uAo, q, 0).rg;
            if (s.y <= 0.0) {
                continue;
            }
            float relative = (s.y - centre.y) / (0.01 * centre.y);
            float w = 1.0 / (1.0 + relative * relative);
            sum += w * s.r;
            weights += w;
        }
    }
    fragColor = vec4(weights > 0.0 ? sum / weights : centre.r, 0.0, 0.0, 1.0);
}

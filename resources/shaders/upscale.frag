#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Upscale of a frame drawn at a reduced size (the camera moving) into the
// target: the composited colour bilinearly (no blocks), and the VSS
// iso-lines drawn here, at the target's resolution, from the bilinear VSS
// height. The VSS is smooth, so its bilinear height is close to the exact
// one; lines drawn at the reduced size would be as many times wider and
// blurred as the size is smaller (a quarter-size frame: 6 px soft bands for
// 1.5 px lines). They are vss.frag's iso-lines (same levels, width in target
// pixels, ink from the colour underneath); where the VSS shows only partly
// (next to a vessel, under a translucent object) they fade with its
// visibility, which the composite put in the alpha channel. Two bilinear
// taps a pixel: on software rasterisers a full-size pass costs about what
// a bilinear blit does only when it samples this little.
// Built with COLOR_ONLY for the parts of the target no iso-line reaches
// (UpscaleTiles.h): one tap a pixel, the same pixels there.

in vec2 vUv;

uniform sampler2D uColor;   // composited RGBA8, linear filtering: rgb, a = the VSS's visibility
uniform sampler2D uHeight;  // R32F at the render size, linear filtering: z' on void pixels
uniform int uIsoLines;      // N; 0 = none (then uHeight is not read)
uniform float uIsoWidth;    // line width in target pixels
uniform float uIsoStrength; // 0..1

out vec4 fragColor;

void main() {
    vec4 composited = textureLod(uColor, vUv, 0.0);
    vec3 color = composited.rgb;
#ifndef COLOR_ONLY
    if (uIsoLines > 0) {
        // On vessel pixels the height is the vessel's own z, which meets z'
        // at the contour; the visibility fades the lines out there.
        float z = clamp(textureLod(uHeight, vUv, 0.0).r, 0.0, 1.0);
        float perPixel = length(vec2(dFdx(z), dFdy(z))) * float(uIsoLines);
        float q = z * float(uIsoLines);
        float bands = min(fract(q), 1.0 - fract(q));
        float pixels = bands / max(perPixel, 1e-6);
        float half_ = 0.5 * uIsoWidth;
        float coverage = 1.0 - smoothstep(half_ - 0.5, half_ + 0.5, pixels);
        float luminance = dot(color, vec3(0.2126, 0.7152, 0.0722));
        vec3 ink = luminance > 0.3 ? color * 0.15 : vec3(0.8);
        color = mix(color, ink, coverage * clamp(uIsoStrength, 0.0, 1.0) * composited.a);
    }
#endif
    fragColor = vec4(color, 1.0);
}

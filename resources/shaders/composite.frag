#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Composite: the translucent objects over the shaded vessels over the shaded
// VSS over the background.
// Vessel pixels keep their own colour: the VSS never covers a vessel.
// With ambient occlusion, the VSS and (half as much) the vessels darken by
// the blurred occlusion times the strength.
// For the "upscale" pass (uVssVisibility) the alpha says how visible the VSS
// is at the pixel (its opacity, minus what vessels and translucent objects
// cover): that pass draws the iso-lines at the target's resolution there.

in vec2 vUv;

uniform sampler2D uVessels;  // RGBA8, alpha 1 on vessel pixels, 0 elsewhere
uniform sampler2D uVss;      // RGBA8, alpha = VSS opacity (0 where there is no VSS)
uniform bool uUseVss;
uniform vec3 uBackground;    // sRGB
uniform sampler2D uAo;       // R8: blurred occlusion in [0, 1], bilinear
uniform float uAoStep;       // 1, or 2: uAo holds every second pixel per axis
uniform bool uUseAo;
uniform float uAoStrength;   // 0..1
// The translucent objects (premultiplied colour, coverage), over everything.
uniform sampler2D uTranslucent;
uniform bool uUseTranslucent;
uniform bool uVssVisibility;  // alpha = the VSS's visibility instead of 1

out vec4 fragColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 vessel = texelFetch(uVessels, p, 0);
    vec3 color = uBackground;
    float visibility = 0.0;
    // uAo's texel i is this frame's pixel i * uAoStep: at step 1 the centre
    // of pixel p is the centre of texel p (the texel itself).
    vec2 aoTexel = (gl_FragCoord.xy - 0.5) / uAoStep + 0.5;
    float occlusion = uUseAo ? clamp(uAoStrength, 0.0, 1.0) *
                                   texture(uAo, aoTexel / vec2(textureSize(uAo, 0))).r
                             : 0.0;
    if (uUseVss) {
        vec4 vss = texelFetch(uVss, p, 0);
        color = mix(color, vss.rgb * (1.0 - occlusion), vss.a);
        visibility = vss.a * (1.0 - vessel.a);
    }
    color = mix(color, vessel.rgb * (1.0 - 0.5 * occlusion), vessel.a);
    if (uUseTranslucent) {
        vec4 layer = texelFetch(uTranslucent, p, 0);
        color = layer.rgb + color * (1.0 - layer.a);
        visibility *= 1.0 - layer.a;
    }
    fragColor = vec4(color, uVssVisibility ? visibility : 1.0);
}

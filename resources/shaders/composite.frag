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
// Built with REDUCED_VSS when the VSS was solved and shaded below the render
// size (a moving frame: the vessels drawn sharper than the VSS): its colour
// is interpolated from its void pixels only, so no colour of the VSS under a
// vessel bleeds past the render size's sharper silhouette.

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
#ifdef REDUCED_VSS
uniform float uVssOpacity;  // the VSS's opacity (uVss: premultiplied, alpha 0 on its vessels)

// The VSS's colour at this render pixel from its smaller image (linear
// filtering): premultiplied by a weight that is 0 on its vessel pixels, so
// one bilinear tap averages the void texels of the four around. Where none
// of them is void (the pixel lies inside the VSS's wider vessel mask), the
// void texels of the 4x4 around (four bilinear taps); where none is either,
// no VSS.
vec4 reducedVss(vec2 fragCoord) {
    vec2 vssSize = vec2(textureSize(uVss, 0));
    vec2 uv = fragCoord / vec2(textureSize(uVessels, 0));
    vec4 v = texture(uVss, uv);
    if (v.a < 1e-3) {
        vec2 texel = 1.0 / vssSize;
        v = texture(uVss, uv + vec2(-texel.x, -texel.y)) + texture(uVss, uv + vec2(texel.x, -texel.y)) +
            texture(uVss, uv + vec2(-texel.x, texel.y)) + texture(uVss, uv + vec2(texel.x, texel.y));
    }
    return v.a < 1e-4 ? vec4(0.0) : vec4(v.rgb / v.a, uVssOpacity);
}
#endif

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
#ifdef REDUCED_VSS
        // (Vessel pixels hide it: not read there.)
        vec4 vss = vessel.a < 1.0 ? reducedVss(gl_FragCoord.xy) : vec4(0.0);
#else
        vec4 vss = texelFetch(uVss, p, 0);
#endif
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

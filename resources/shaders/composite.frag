#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Composite: the shaded vessels over the shaded VSS over the background.
// Vessel pixels keep their own colour: the VSS never covers a vessel.

in vec2 vUv;

uniform sampler2D uVessels;  // RGBA8, alpha 1 on vessel pixels, 0 elsewhere
uniform sampler2D uVss;      // RGBA8, alpha = VSS opacity (0 where there is no VSS)
uniform bool uUseVss;
uniform vec3 uBackground;    // sRGB

out vec4 fragColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 vessel = texelFetch(uVessels, p, 0);
    vec3 color = uBackground;
    if (uUseVss) {
        vec4 vss = texelFetch(uVss, p, 0);
        color = mix(color, vss.rgb, vss.a);
    }
    color = mix(color, vessel.rgb, vessel.a);
    fragColor = vec4(color, 1.0);
}

#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Vessel surface: neutral material or an array through a 1-D colour map,
// Blinn-Phong with a key light near the eye (headlight) plus ambient.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;

uniform bool uUseArray;          // false: neutral material
uniform vec3 uBaseColor;         // neutral material, sRGB
uniform vec3 uNoDataColor;       // for NaN / missing values, sRGB
uniform sampler1D uLut;          // colour map, sRGB, linear filtering
uniform float uLutSize;          // texels in uLut
uniform vec2 uRange;             // values mapped to the first and last LUT entry
uniform bool uLighting;          // false: flat colours
uniform vec3 uLightDirection;    // towards the key light, view space, unit length
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;

layout(location = 0) out vec4 fragColor;
// The parameter value for the G-buffer (NaN = no data); ignored when the
// framebuffer has no second colour attachment.
layout(location = 1) out float fragParameter;

float parameterValue() {
    return (uUseArray && vScalar.y >= 0.5) ? vScalar.x : uintBitsToFloat(0x7fc00000u);
}

vec3 surfaceColor() {
    if (!uUseArray) {
        return uBaseColor;
    }
    // A fragment between a valid and an invalid vertex belongs to the nearer one.
    if (vScalar.y < 0.5) {
        return uNoDataColor;
    }
    float span = uRange.y - uRange.x;
    float t = span > 0.0 ? clamp((vScalar.x - uRange.x) / span, 0.0, 1.0) : 0.5;
    // Texel centres: t = 0 hits the first entry exactly, t = 1 the last.
    float u = (t * (uLutSize - 1.0) + 0.5) / uLutSize;
    return texture(uLut, u).rgb;
}

void main() {
    fragParameter = parameterValue();
    vec3 base = surfaceColor();
    if (!uLighting) {
        fragColor = vec4(base, 1.0);
        return;
    }
    vec3 n = normalize(vNormalView);
    vec3 v = normalize(-vPositionView);
    // Two-sided: open meshes and inconsistent windings show their inside lit too.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    vec3 l = uLightDirection;
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
    vec3 color = base * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular);
    fragColor = vec4(min(color, vec3(1.0)), 1.0);
}

#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Vessel surface: neutral material or an array through a 1-D colour map,
// Blinn-Phong with a key light near the eye (headlight) plus ambient.
// Optionally a depth cue on the vessel itself (VesselCue in MeshRenderer.h).

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;

uniform bool uUseArray;          // false: neutral material
uniform vec3 uBaseColor;         // neutral material, sRGB
uniform vec3 uNoDataColor;       // for NaN / missing values, sRGB
uniform sampler1D uLut;          // colour map, sRGB, linear filtering
uniform float uLutSize;          // texels in uLut
uniform vec2 uRange;             // values mapped to the first and last LUT entry
uniform int uBins;               // >= 2: uLut holds exactly uBins bin colours (nearest)
// Vessel cue: 0 none, 1 chromadepth, 2 pseudo-chromadepth, 3 fog, 4 Fresnel-edge
// pseudo-chromadepth (the values of VesselCue).
uniform int uCue;
uniform sampler1D uCueLut;       // the cue's depth scale, sRGB, linear filtering
uniform float uCueLutSize;
uniform vec2 uCueDepthRange;     // linear view depth mapped to t = 0 and t = 1
uniform vec3 uFogColor;          // the background, sRGB
uniform float uFogStrength;      // fog weight at t = 1
uniform float uFresnelExponent;  // k in (1 - |n.v|)^k
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
    if (uBins >= 2) {
        // The bin's texel centre: bin = min(floor(t * N), N - 1), like colormaps::binIndex.
        float bins = float(uBins);
        return texture(uLut, (min(floor(t * bins), bins - 1.0) + 0.5) / bins).rgb;
    }
    // Texel centres: t = 0 hits the first entry exactly, t = 1 the last.
    float u = (t * (uLutSize - 1.0) + 0.5) / uLutSize;
    return texture(uLut, u).rgb;
}

// Normalised depth: 0 at uCueDepthRange.x (nearest), 1 at .y; 0 for a flat range.
float cueDepth() {
    float span = uCueDepthRange.y - uCueDepthRange.x;
    if (!(span > 1e-6 * max(abs(uCueDepthRange.y), 1.0))) {
        return 0.0;
    }
    return clamp((-vPositionView.z - uCueDepthRange.x) / span, 0.0, 1.0);
}

vec3 cueScale(float t) {
    return texture(uCueLut, (t * (uCueLutSize - 1.0) + 0.5) / uCueLutSize).rgb;
}

void main() {
    fragParameter = parameterValue();
    vec3 base = surfaceColor();
    vec3 n = normalize(vNormalView);
    vec3 v = normalize(-vPositionView);
    // Two-sided: open meshes and inconsistent windings show their inside lit too.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    float t = cueDepth();
    if (uCue == 1 || uCue == 2) {
        base = cueScale(t);
    } else if (uCue == 4) {
        // Behrendt et al. 2017: the depth colour at silhouettes only.
        float fresnel = pow(clamp(1.0 - abs(dot(n, v)), 0.0, 1.0), uFresnelExponent);
        base = mix(base, cueScale(t), fresnel);
    }
    if (!uLighting) {
        fragColor = vec4(uCue == 3 ? mix(base, uFogColor, uFogStrength * t) : base, 1.0);
        return;
    }
    vec3 l = uLightDirection;
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
    vec3 color = min(base * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular), vec3(1.0));
    if (uCue == 3) {
        // Kersten-Oertel et al. 2014: fade towards the background with depth.
        color = mix(color, uFogColor, uFogStrength * t);
    }
    fragColor = vec4(color, 1.0);
}

#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// The vessel material, shared by the forward shader (mesh.frag) and the
// deferred one (vessel.frag): the program is built from this file followed by
// one of them. Neutral material or an array through a 1-D colour map,
// Blinn-Phong with a key light near the eye plus ambient, optionally a depth
// cue on the vessel itself (VesselCue in MeshRenderer.h).

// The scene's material (per object in the forward passes: MeshRenderer sets
// these before each object; the deferred pass reads a per-object table).
uniform bool uUseArray;          // false: neutral material
uniform vec3 uBaseColor;         // neutral material, sRGB
uniform vec3 uNoDataColor;       // for NaN / missing values, sRGB
uniform sampler1D uLut;          // colour map, sRGB, linear filtering
uniform float uLutSize;          // texels in uLut
uniform vec2 uRange;             // values mapped to the first and last LUT entry
uniform float uOpacity;          // forward passes: the object's opacity (premultiplied output)
uniform int uBins;               // >= 2: uLut holds exactly uBins bin colours (nearest)
uniform bool uLabels;            // the array holds labels: one palette colour per label
uniform sampler1D uLabelPalette;  // colormaps::labelPalette(), sRGB, nearest
uniform int uLabelPaletteSize;
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

// What one object shows: an array through the colour map over `range`, its
// labels in the label palette (`labels`), or the neutral material `base`.
struct Material {
    bool useArray;
    vec3 base;
    vec2 range;
    bool labels;
};

// The material of the uniforms.
Material uniformMaterial() {
    return Material(uUseArray, uBaseColor, uRange, uLabels);
}

// The colour of a value of the array (valid = false: no data) or the neutral
// material; for labels the palette colour of label index `label`.
vec3 surfaceColor(Material m, float value, bool valid, float label) {
    if (!m.useArray) {
        return m.base;
    }
    if (!valid) {
        return uNoDataColor;
    }
    if (m.labels) {
        int index = int(floor(label + 0.5)) % max(uLabelPaletteSize, 1);
        return texelFetch(uLabelPalette, index, 0).rgb;
    }
    float span = m.range.y - m.range.x;
    float t = span > 0.0 ? clamp((value - m.range.x) / span, 0.0, 1.0) : 0.5;
    if (uBins >= 2) {
        // The bin's texel centre: bin = min(floor(t * N), N - 1), like colormaps::binIndex.
        float bins = float(uBins);
        return texture(uLut, (min(floor(t * bins), bins - 1.0) + 0.5) / bins).rgb;
    }
    // Texel centres: t = 0 hits the first entry exactly, t = 1 the last.
    float u = (t * (uLutSize - 1.0) + 0.5) / uLutSize;
    return texture(uLut, u).rgb;
}

// Normalised depth of a linear view depth: 0 at uCueDepthRange.x (nearest),
// 1 at .y; 0 for a flat range.
float cueDepth(float linearDepth) {
    float span = uCueDepthRange.y - uCueDepthRange.x;
    if (!(span > 1e-6 * max(abs(uCueDepthRange.y), 1.0))) {
        return 0.0;
    }
    return clamp((linearDepth - uCueDepthRange.x) / span, 0.0, 1.0);
}

vec3 cueScale(float t) {
    return texture(uCueLut, (t * (uCueLutSize - 1.0) + 0.5) / uCueLutSize).rgb;
}

// The shaded vessel colour at a view-space position with its (not
// necessarily unit) view-space normal; `label`: the label index (labels only).
vec3 shadeVessel(Material m, vec3 positionView, vec3 normalView, float value, bool valid,
                 float label) {
    vec3 base = surfaceColor(m, value, valid, label);
    vec3 n = normalize(normalView);
    vec3 v = normalize(-positionView);
    // Two-sided: open meshes and inconsistent windings show their inside lit too.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    float t = cueDepth(-positionView.z);
    if (uCue == 1 || uCue == 2) {
        base = cueScale(t);
    } else if (uCue == 4) {
        // Behrendt et al. 2017: the depth colour at silhouettes only.
        float fresnel = pow(clamp(1.0 - abs(dot(n, v)), 0.0, 1.0), uFresnelExponent);
        base = mix(base, cueScale(t), fresnel);
    }
    if (!uLighting) {
        return uCue == 3 ? mix(base, uFogColor, uFogStrength * t) : base;
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
    return color;
}

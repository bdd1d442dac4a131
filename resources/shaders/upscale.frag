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
// Built with EDGES (with or without COLOR_ONLY) for the rectangles that
// hold a vessel silhouette (drawn after the rest, over rects.vert): where
// the pixel's bilinear footprint has vessel and non-vessel texels (by the
// render size's depth), the silhouette is the
// straight edge rebuilt from the render size's staircase on the CPU
// (SilhouetteRuns.h) through the footprint's pair of texels nearest the
// pixel that straddles it (without one, the 0.5 contour of the bilinear
// vessel coverage), drawn at the target's resolution with one target pixel
// of anti-aliasing, each side coloured from its own texels only (the
// bilinear weights of that side, renormalised): no render pixel's blur or
// step across the edge, and neither side's colour bleeding into the other.
// Elsewhere the same single tap.

in vec2 vUv;

uniform sampler2D uColor;   // composited RGBA8, linear filtering: rgb, a = the VSS's visibility
uniform sampler2D uHeight;  // R32F at the render size, linear filtering: z' on void pixels
uniform int uIsoLines;      // N; 0 = none (then uHeight is not read)
uniform float uIsoWidth;    // line width in target pixels
uniform float uIsoStrength; // 0..1
#ifdef EDGES
uniform sampler2D uDepth;        // R32F linear depth at the render size: finite on vessel pixels
uniform vec2 uTexelsPerPixel;    // render pixels per target pixel, per axis
// RGBA8 at the render size (SilhouetteRuns.h): per texel, where the
// silhouette through its pair with the texel above crosses the pair's
// left and right sides (rg), and through its pair with the texel to the
// right the pair's lower and upper sides (ba), + 0.5 texel.
uniform sampler2D uRuns;
#endif

out vec4 fragColor;

#ifdef EDGES
// The composited colour at uv near a vessel silhouette (`bilinear`: its
// bilinear tap, kept where the footprint is all one kind). The gather's
// and the fetches' texels are the footprint's: (0, 1), (1, 1), (1, 0),
// (0, 0) from its lower left texel i0, gathered at the block's centre so
// that no rounding picks another block.
vec4 edgeAware(vec2 uv, vec4 bilinear) {
    vec2 size = vec2(textureSize(uColor, 0));
    vec2 p = uv * size - 0.5;
    vec2 i0 = floor(p);
    vec4 depth = textureGather(uDepth, (i0 + 1.0) / size, 0);
    // 1 on vessel texels (finite depth), 0 elsewhere (+Inf).
    vec4 v = vec4(lessThan(depth, vec4(3.0e38)));
    float vessels = dot(v, vec4(1.0));
    if (vessels == 0.0 || vessels == 4.0) {
        return bilinear;
    }
    vec2 f = p - i0;
    ivec2 t0 = ivec2(i0);
    // The bilinear coverage and its gradient per target pixel: the edge's
    // direction, and where no run is found its 0.5 contour.
    vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    float coverage = dot(w, v);
    vec2 gradient = vec2((1.0 - f.y) * (v.z - v.w) + f.y * (v.y - v.x),
                         (1.0 - f.x) * (v.x - v.w) + f.x * (v.y - v.z)) *
                    uTexelsPerPixel;
    float alpha = clamp((coverage - 0.5) / max(length(gradient), 1e-4) + 0.5, 0.0, 1.0);
    // A flatter edge is a run of pairs along x (one above the other), a
    // steeper one along y. The pair nearest the pixel, else the other.
    bool flatter = abs(gradient.y) >= abs(gradient.x);
    ivec2 along = flatter ? ivec2(1, 0) : ivec2(0, 1);
    ivec2 across = flatter ? ivec2(0, 1) : ivec2(1, 0);
    float fa = flatter ? f.x : f.y;
    float fb = flatter ? f.y : f.x;
    vec2 pair0 = flatter ? v.wx : v.wz;  // (low, other) of the footprint's first pair
    vec2 pair1 = flatter ? v.zy : v.xy;
    bool second = (fa >= 0.5 && pair1.x != pair1.y) || pair0.x == pair0.y;
    vec2 pair = second ? pair1 : pair0;
    if (pair.x != pair.y) {
        // The silhouette through the pair: its offset from the pair's
        // midline at the pixel, and its slope (texels).
        vec4 runs = texelFetch(uRuns, t0 + (second ? along : ivec2(0)), 0) - 0.5;
        vec2 sides = flatter ? runs.xy : runs.zw;
        vec2 edge = vec2(mix(sides.x, sides.y, fa - (second ? 0.5 : -0.5)), sides.y - sides.x);
        float tAlong = flatter ? uTexelsPerPixel.x : uTexelsPerPixel.y;
        float tAcross = flatter ? uTexelsPerPixel.y : uTexelsPerPixel.x;
        // Target pixels from the line (towards `across`), across it.
        float d = (fb - 0.5 - edge.x) / tAcross /
                  sqrt(1.0 + edge.y * edge.y * tAlong * tAlong / (tAcross * tAcross));
        float lowSide = clamp(0.5 - d, 0.0, 1.0);
        alpha = pair.x == 1.0 ? lowSide : 1.0 - lowSide;
    }
    ivec2 hi = textureSize(uColor, 0) - 1;
    vec4 c01 = texelFetch(uColor, clamp(t0 + ivec2(0, 1), ivec2(0), hi), 0);
    vec4 c11 = texelFetch(uColor, clamp(t0 + ivec2(1, 1), ivec2(0), hi), 0);
    vec4 c10 = texelFetch(uColor, clamp(t0 + ivec2(1, 0), ivec2(0), hi), 0);
    vec4 c00 = texelFetch(uColor, clamp(t0, ivec2(0), hi), 0);
    // Each side's colour from its texels; the small floor keeps a side's
    // colour defined where its weights vanish (there it is not seen).
    vec4 wv = (w + 1e-3) * v;
    vec4 wo = (w + 1e-3) * (1.0 - v);
    vec4 vessel = (wv.x * c01 + wv.y * c11 + wv.z * c10 + wv.w * c00) / dot(wv, vec4(1.0));
    vec4 other = (wo.x * c01 + wo.y * c11 + wo.z * c10 + wo.w * c00) / dot(wo, vec4(1.0));
    return mix(other, vessel, alpha);
}
#endif

void main() {
    vec4 composited = textureLod(uColor, vUv, 0.0);
#ifdef EDGES
    composited = edgeAware(vUv, composited);
#endif
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

#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// VSS shading (VSS.md, "Shading on the VSS"): the void space surface's
// normalised depth z' through a depth colour scale, N iso-lines of constant
// on-screen width (anti-aliased with the screen-space gradient of z'), and
// Blinn-Phong with the normals of the height field, lit like the vessels.
// The slope is a weighted least-squares plane fit over the 5x5 VSS pixels
// around (never across a vessel contour, where z' meets the vessel's depth
// and the one-pixel gradient is steep and noisy: that gave bright specular
// specks along contours and at branch tips); the specular term also fades
// where few VSS pixels support the fit (next to contours), and the
// highlight widens and dims where the normal turns fast (Toksvig: the mean of
// the normals around has length < 1), which removes the small bright specks
// on the tight bends of the VSS around branch tips.
// Output: the shaded VSS with alpha = the opacity where a VSS exists, 0
// elsewhere (uVoidPremultiplied: premultiplied, and 0 on vessel pixels too).

in vec2 vUv;

uniform sampler2D uHeight;   // R32F: z' on void pixels, z on vessel pixels, < -0.5 = no VSS
uniform sampler2D uLinearDepth;  // R32F: vessel depth, +Inf off the vessels
uniform sampler1D uScale;    // depth colour scale, near (0) to far (1), sRGB
uniform float uScaleSize;    // texels in uScale
uniform float uDmin;         // depth range of z in scene units
uniform float uDmax;
uniform float uPixelScale;   // scene units per pixel per scene unit of depth: 2 tan(fov/2) / H
uniform int uIsoLines;       // N; 0 = none
uniform float uIsoWidth;     // line width in pixels
uniform float uIsoStrength;  // 0..1
uniform float uLighting;     // 0 = flat colours, 1 = full Blinn-Phong
uniform float uOpacity;      // 0..1, the VSS over the background
uniform vec3 uLightDirection;
uniform float uAmbient;
uniform float uDiffuse;
uniform float uSpecular;
uniform float uShininess;
// A VSS shaded below the render size (composite.frag's REDUCED_VSS):
// premultiplied colour, alpha 0 on vessel pixels. Only the last write
// depends on it.
uniform bool uVoidPremultiplied;
// Preview frames while the camera moves are built with QUICK_NORMALS
// defined (a variant, not a uniform: llvmpipe runs both sides of a branch):
// slopes from differences 1 and 2 px apart away from contours and a plane
// fit over samples 2 px apart next to one (no Toksvig, no mean samples).
#ifdef QUICK_NORMALS
const bool kQuickNormals = true;
#else
const bool kQuickNormals = false;
#endif
// Exact frames are built with SLOPE_TEXTURE defined when the solver's thread
// fitted the slopes already (vss::fittedSlopes: the same fit as
// fittedGradient below, once per solve instead of every frame):
// uSlope = (dz'/dx, dz'/dy, support, coherence) on void pixels, the
// coherence being Toksvig's length below (vss::addNormalCoherence).
#ifdef SLOPE_TEXTURE
uniform sampler2D uSlope;
#endif

out vec4 fragColor;

bool hasVss(float h) {
    return h > -0.5;
}

float heightAt(ivec2 p, ivec2 size) {
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) {
        return -1.0;
    }
    return texelFetch(uHeight, p, 0).r;
}

// One derivative of z' per pixel: central where both neighbours have a VSS,
// one-sided where one has, 0 where none has.
float derivative(float minus, float centre, float plus) {
    bool m = hasVss(minus);
    bool p = hasVss(plus);
    if (m && p) {
        return 0.5 * (plus - minus);
    }
    if (p) {
        return plus - centre;
    }
    if (m) {
        return centre - minus;
    }
    return 0.0;
}

bool isVessel(ivec2 p) {
    return texelFetch(uLinearDepth, p, 0).r < 1e30;
}

// The mean offset (x, y) and z' of the VSS (non-vessel) pixels within
// `radius` (chessboard) of q, a VSS pixel itself: vss::fittedSlopes' samples
// next to contours, each at its pixels' centroid.
vec3 meanSample(ivec2 q, ivec2 size, int radius) {
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int j = -radius; j <= radius; ++j) {
        for (int i = -radius; i <= radius; ++i) {
            ivec2 r = q + ivec2(i, j);
            if (r.x < 0 || r.y < 0 || r.x >= size.x || r.y >= size.y) {
                continue;
            }
            float hr = heightAt(r, size);
            if (hasVss(hr) && !isVessel(r)) {
                sum += vec3(float(i), float(j), hr);
                count += 1.0;
            }
        }
    }
    return sum / count;
}

// dz'/dx, dz'/dy per pixel: a weighted least-squares plane (offset and
// slope, so the centre's own value does not pin it) through the VSS pixels of
// a 5x5 window of samples `stride` pixels apart (Gaussian weights in samples),
// each sample the mean of the VSS pixels within `radius` (chessboard) around
// it (meanSample; radius 0: the pixel); `support` = the weight of those pixels over the
// whole window's. Falls back to `fallback` when they do not determine a plane.
vec2 fittedGradient(ivec2 p, ivec2 size, float z, vec2 fallback, int stride, int radius,
                    out float support) {
    float sw = 0.0;
    float sx = 0.0;
    float sy = 0.0;
    float sh = 0.0;
    float sxx = 0.0;
    float sxy = 0.0;
    float syy = 0.0;
    float sxh = 0.0;
    float syh = 0.0;
    float total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy) * stride;
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) {
                continue;  // the image border is no contour
            }
            float w = exp(-0.25 * float(dx * dx + dy * dy));
            total += w;
            float hq = heightAt(q, size);
            if (!hasVss(hq) || isVessel(q)) {
                continue;
            }
            vec2 offset = vec2(0.0);
            if (radius > 0) {
                vec3 m = meanSample(q, size, radius);
                offset = m.xy;
                hq = m.z;
            }
            float x = float(dx * stride) + offset.x;
            float y = float(dy * stride) + offset.y;
            float dh = hq - z;
            sw += w;
            sx += w * x;
            sy += w * y;
            sh += w * dh;
            sxx += w * x * x;
            sxy += w * x * y;
            syy += w * y * y;
            sxh += w * x * dh;
            syh += w * y * dh;
        }
    }
    support = total > 0.0 ? sw / total : 0.0;
    if (sw <= 0.0) {
        return fallback;
    }
    // Centred sums: the plane's offset drops out.
    float cxx = sxx - sx * sx / sw;
    float cxy = sxy - sx * sy / sw;
    float cyy = syy - sy * sy / sw;
    float cxh = sxh - sx * sh / sw;
    float cyh = syh - sy * sh / sw;
    float det = cxx * cyy - cxy * cxy;
    if (det < 0.05 * max(cxx * cyy, 1e-12)) {
        return fallback;
    }
    return vec2(cyy * cxh - cxy * cyh, cxx * cyh - cxy * cxh) / det;
}

// The normal from a central difference at p, or none (w = 0) where p or a
// neighbour is off the VSS or on a vessel; w = -1 off the image.
vec4 sparseNormal(ivec2 p, ivec2 size, float scale) {
    if (p.x < 1 || p.y < 1 || p.x >= size.x - 1 || p.y >= size.y - 1) {
        return vec4(0.0, 0.0, 0.0, -1.0);
    }
    float c = heightAt(p, size);
    float xm = heightAt(p - ivec2(1, 0), size);
    float xp = heightAt(p + ivec2(1, 0), size);
    float ym = heightAt(p - ivec2(0, 1), size);
    float yp = heightAt(p + ivec2(0, 1), size);
    if (!hasVss(c) || !hasVss(xm) || !hasVss(xp) || !hasVss(ym) || !hasVss(yp) || isVessel(p)) {
        return vec4(0.0);
    }
    vec2 g = 0.5 * vec2(xp - xm, yp - ym);
    return vec4(normalize(vec3(g * scale, 1.0)), 1.0);
}

void main() {
    ivec2 size = textureSize(uHeight, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = heightAt(p, size);
    if (!hasVss(z)) {
        fragColor = vec4(0.0);
        return;
    }
    float support = 1.0;
    bool vessel = isVessel(p);
    // The one-pixel central difference: the slope on vessel pixels, and the
    // per-pixel fit's fallback. The quick and the slope-texture variants
    // take void pixels' slopes elsewhere, so they read these four heights
    // only for vessel pixels (llvmpipe skips a branch no pixel of a block takes).
    vec2 grad = vec2(0.0);
#if defined(QUICK_NORMALS) || defined(SLOPE_TEXTURE)
    if (vessel)
#endif
    {
        grad = vec2(derivative(heightAt(p - ivec2(1, 0), size), z, heightAt(p + ivec2(1, 0), size)),
                    derivative(heightAt(p - ivec2(0, 1), size), z, heightAt(p + ivec2(0, 1), size)));
    }
#ifdef SLOPE_TEXTURE
    vec4 fitted = vec4(0.0, 0.0, 1.0, 1.0);
#endif
    if (!vessel && kQuickNormals) {
        // Never across a contour: vessel neighbours count as missing.
        ivec2 dx = ivec2(1, 0);
        ivec2 dy = ivec2(0, 1);
        float xm = isVessel(p - dx) ? -1.0 : heightAt(p - dx, size);
        float xp = isVessel(p + dx) ? -1.0 : heightAt(p + dx, size);
        float ym = isVessel(p - dy) ? -1.0 : heightAt(p - dy, size);
        float yp = isVessel(p + dy) ? -1.0 : heightAt(p + dy, size);
        grad = vec2(derivative(xm, z, xp), derivative(ym, z, yp));
        float xm2 = isVessel(p - 2 * dx) ? -1.0 : heightAt(p - 2 * dx, size);
        float xp2 = isVessel(p + 2 * dx) ? -1.0 : heightAt(p + 2 * dx, size);
        float ym2 = isVessel(p - 2 * dy) ? -1.0 : heightAt(p - 2 * dy, size);
        float yp2 = isVessel(p + 2 * dy) ? -1.0 : heightAt(p + 2 * dy, size);
        // Away from contours, the mean of the differences over 2 px: the
        // preview solve's interpolation bends z' at its cells' edges, which
        // one-pixel slopes light as seams across the void.
        if (hasVss(xm) && hasVss(xp) && hasVss(xm2) && hasVss(xp2)) {
            grad.x = 0.125 * (xp2 - xm2) + 0.25 * (xp - xm);
        }
        if (hasVss(ym) && hasVss(yp) && hasVss(ym2) && hasVss(yp2)) {
            grad.y = 0.125 * (yp2 - ym2) + 0.25 * (yp - ym);
        }
        // The share of the eight samples with VSS: the specular fades over
        // two pixels next to a contour, not on and off from pixel to pixel
        // along the silhouette's staircase (which lit its corners as specks).
        support = (float(hasVss(xm)) + float(hasVss(xp)) + float(hasVss(ym)) + float(hasVss(yp)) +
                   float(hasVss(xm2)) + float(hasVss(xp2)) + float(hasVss(ym2)) +
                   float(hasVss(yp2))) / 8.0;
        // Next to a contour (one of the eight samples missing) the
        // silhouette's pixel staircase ripples z' (the teeth the settled
        // frame's wide fit keeps out of the light): there the slope is the
        // plane fit over 5x5 samples 2 px apart (4-5 window px at the
        // budget's scales, as the settled frame's 4 px). Fitting out to
        // 3 px (a vessel 3 px away) took the teeth from 1.6 to 1.1 x the
        // settled frame's but cost ~3 ms more a moving frame on llvmpipe.
        if (support < 1.0) {
            float ignored = 1.0;
            grad = fittedGradient(p, size, z, grad, 2, 0, ignored);
        }
    } else if (!vessel) {
#ifdef SLOPE_TEXTURE
        fitted = texelFetch(uSlope, p, 0);
        grad = fitted.xy;
        support = fitted.z;
#else
        grad = fittedGradient(p, size, z, grad, 1, 0, support);
        // Within 8 px of a contour the silhouette's pixel staircase ripples
        // the VSS (teeth along the edges under the light): where the window
        // of samples 4 px apart misses samples, its fit is taken, each
        // sample the mean over 5x5 pixels.
        float wide = 1.0;
        fittedGradient(p, size, z, grad, 4, 0, wide);
        if (wide < 0.999) {
            grad = fittedGradient(p, size, z, grad, 4, 2, wide);
        }
#endif
    }

    // Colour: texel centres, so z' = 0 hits the first entry and 1 the last.
    float t = clamp(z, 0.0, 1.0);
    vec3 base = texture(uScale, (t * (uScaleSize - 1.0) + 0.5) / uScaleSize).rgb;

    // Lighting: the height field h = depth in scene units over a grid of
    // pixels that are (depth * uPixelScale) scene units wide; x right, y up,
    // depth away from the viewer. Its normal faces the viewer.
    float range = max(uDmax - uDmin, 0.0);
    float depth = uDmin + t * range;
    float pixel = max(depth * uPixelScale, 1e-12);
    vec3 n = normalize(vec3(grad * range / pixel, 1.0));
    vec3 l = uLightDirection;
    vec3 v = vec3(0.0, 0.0, 1.0);
    vec3 hv = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    // Toksvig: normals 3 px around; missing ones count as turned away.
    float shininess = uShininess;
    float specularScale = smoothstep(0.55, 0.9, support);
#ifdef SLOPE_TEXTURE
    if (!vessel) {
        float len = clamp(fitted.w, 1e-3, 1.0);
        shininess = len * uShininess / (len + uShininess * (1.0 - len));
        specularScale *= (1.0 + shininess) / (1.0 + uShininess);
    }
#else
    if (!vessel && !kQuickNormals) {
        float scale = range / pixel;
        vec3 sum = n;
        float count = 1.0;
        const ivec2 around[4] = ivec2[4](ivec2(3, 0), ivec2(-3, 0), ivec2(0, 3), ivec2(0, -3));
        for (int i = 0; i < 4; ++i) {
            vec4 m = sparseNormal(p + around[i], size, scale);
            if (m.w >= 0.0) {
                sum += m.xyz;
                count += 1.0;
            }
        }
        float len = clamp(length(sum) / count, 1e-3, 1.0);
        shininess = len * uShininess / (len + uShininess * (1.0 - len));
        specularScale *= (1.0 + shininess) / (1.0 + uShininess);
    }
#endif
    float specular = diffuse > 0.0 ? pow(max(dot(n, hv), 0.0), shininess) : 0.0;
    specular *= specularScale;
    vec3 lit = base * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular);
    vec3 color = mix(base, min(lit, vec3(1.0)), clamp(uLighting, 0.0, 1.0));

    // Iso-lines at z' = k / N: distance to the nearest level in pixels.
    if (uIsoLines > 0 && uIsoStrength > 0.0) {
        float q = t * float(uIsoLines);
        float bands = min(fract(q), 1.0 - fract(q));
        float perPixel = length(grad) * float(uIsoLines);
        float pixels = bands / max(perPixel, 1e-6);
        float half_ = 0.5 * uIsoWidth;
        float coverage = 1.0 - smoothstep(half_ - 0.5, half_ + 0.5, pixels);
        float luminance = dot(color, vec3(0.2126, 0.7152, 0.0722));
        vec3 ink = luminance > 0.3 ? color * 0.15 : vec3(0.8);
        color = mix(color, ink, coverage * clamp(uIsoStrength, 0.0, 1.0));
    }
    float alpha = clamp(uOpacity, 0.0, 1.0);
    if (uVoidPremultiplied) {
        // A VSS below the render size: premultiplied, and transparent on
        // vessel pixels, so that a bilinear tap of the composite averages
        // the void pixels around only.
        alpha = vessel ? 0.0 : alpha;
        color *= alpha;
    }
    fragColor = vec4(color, alpha);
}

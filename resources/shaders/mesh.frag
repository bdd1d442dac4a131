// SPDX-License-Identifier: GPL-3.0-or-later
// Forward vessel shading (after vessel_shading.glsl, which has #version and
// the material): one shaded fragment per rasterised vessel fragment, with
// the material of the uniforms (set per object); also the translucent pass.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;
flat in vec2 vLabel;  // label arrays: (label, 1 + its palette index), per triangle

layout(location = 0) out vec4 fragColor;
// The parameter value (NaN = no data); ignored when the framebuffer has no
// second colour attachment.
layout(location = 1) out float fragParameter;

void main() {
    // A fragment between a valid and an invalid vertex belongs to the nearer one.
    vec2 scalar = uLabels ? vLabel : vScalar;
    bool valid = scalar.y >= 0.5;
    fragParameter = (uUseArray && valid) ? scalar.x : uintBitsToFloat(0x7fc00000u);
    vec3 color = shadeVessel(uniformMaterial(), vPositionView, vNormalView, scalar.x, valid,
                             scalar.y - 1.0);
    // Premultiplied: opaque passes draw with uOpacity = 1 and no blending.
    fragColor = vec4(color * uOpacity, uOpacity);
}

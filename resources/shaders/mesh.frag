// SPDX-License-Identifier: GPL-3.0-or-later
// Forward vessel shading (after vessel_shading.glsl, which has #version and
// the material): one shaded fragment per rasterised vessel fragment, with
// the material of the uniforms (set per object); also the translucent pass.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;

layout(location = 0) out vec4 fragColor;
// The parameter value (NaN = no data); ignored when the framebuffer has no
// second colour attachment.
layout(location = 1) out float fragParameter;

void main() {
    // A fragment between a valid and an invalid vertex belongs to the nearer one.
    bool valid = vScalar.y >= 0.5;
    fragParameter = (uUseArray && valid) ? vScalar.x : uintBitsToFloat(0x7fc00000u);
    vec3 color = shadeVessel(uniformMaterial(), vPositionView, vNormalView, vScalar.x, valid);
    // Premultiplied: opaque passes draw with uOpacity = 1 and no blending.
    fragColor = vec4(color * uOpacity, uOpacity);
}

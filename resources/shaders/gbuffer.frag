#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry pass: the vessels into the G-buffer. Linear view depth is the
// view-space distance along the viewing axis (scene units, > 0 in front of
// the eye), written here rather than reconstructed from the depth buffer.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;
flat in vec2 vLabel;  // label arrays: (label, 1 + its palette index), per triangle

uniform uint uObjectId;  // 1 + the mesh's index in the scene; 0 = no object
uniform bool uUseArray;  // false: no array shown, the parameter is NaN everywhere
uniform bool uLabels;    // the array holds labels: vLabel, not vScalar

layout(location = 0) out float fragLinearDepth;
// View space, facing the viewer; w = 1 where the parameter value is valid, else
// 0; for labels 1 + the label's palette index (exact in half floats).
layout(location = 1) out vec4 fragNormal;
layout(location = 2) out uint fragObjectId;
layout(location = 3) out float fragParameter;  // the array value, NaN = no data

void main() {
    fragLinearDepth = -vPositionView.z;
    vec3 n = normalize(vNormalView);
    if (dot(n, -vPositionView) < 0.0) {
        n = -n;
    }
    // A fragment between a valid and an invalid vertex belongs to the nearer one.
    vec2 scalar = uLabels ? vLabel : vScalar;
    bool valid = uUseArray && scalar.y >= 0.5;
    fragNormal = vec4(n, valid ? (uLabels ? scalar.y : 1.0) : 0.0);
    fragObjectId = uObjectId;
    fragParameter = valid ? scalar.x : uintBitsToFloat(0x7fc00000u);
}

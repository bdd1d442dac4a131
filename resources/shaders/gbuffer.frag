#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry pass: the vessels into the G-buffer. Linear view depth is the
// view-space distance along the viewing axis (scene units, > 0 in front of
// the eye), written here rather than reconstructed from the depth buffer.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vScalar;

uniform uint uObjectId;  // 1 + the mesh's index in the scene; 0 = no object

layout(location = 0) out float fragLinearDepth;
layout(location = 1) out vec4 fragNormal;  // view space, facing the viewer, w = 1
layout(location = 2) out uint fragObjectId;

void main() {
    fragLinearDepth = -vPositionView.z;
    vec3 n = normalize(vNormalView);
    if (dot(n, -vPositionView) < 0.0) {
        n = -n;
    }
    fragNormal = vec4(n, 1.0);
    fragObjectId = uObjectId;
}

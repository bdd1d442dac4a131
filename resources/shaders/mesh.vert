#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Vessel surface: positions and normals to view space, scalar passed through.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
// x = the array value, y = 1 where the value is valid, 0 where it is NaN /
// missing (GLSL does not promise NaN arithmetic, so validity travels apart).
layout(location = 2) in vec2 aScalar;

uniform mat4 uView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;

out vec3 vPositionView;
out vec3 vNormalView;
out vec2 vScalar;
// The same, not interpolated (the triangle's provoking vertex): label arrays
// show one label per triangle, never a label between two others.
flat out vec2 vLabel;

// The G-buffer pass and the shading pass draw the same triangles with
// different fragment shaders; the shading pass tests against the G-buffer's
// depth with GL_LEQUAL, so positions must be bit-identical in both programs.
invariant gl_Position;

void main() {
    vec4 positionView = uView * vec4(aPosition, 1.0);
    vPositionView = positionView.xyz;
    vNormalView = uNormalMatrix * aNormal;
    vScalar = aScalar;
    vLabel = aScalar;
    gl_Position = uProjection * positionView;
}

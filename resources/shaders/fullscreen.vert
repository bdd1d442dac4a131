#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// One triangle that covers the viewport; no vertex buffer (gl_VertexID only).

out vec2 vUv;

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}

#version 410 core
// SPDX-License-Identifier: GPL-3.0-or-later
// Rectangles of the target (RectBatch.h): corners in target pixels, and
// vUv as fullscreen.vert gives it (0..1 over the target), so that the
// full-screen fragment programs draw the same pixels in them.

layout(location = 0) in vec2 aPixel;

uniform vec2 uTargetSize;

out vec2 vUv;

void main() {
    vUv = aPixel / uTargetSize;
    gl_Position = vec4(vUv * 2.0 - 1.0, 0.0, 1.0);
}

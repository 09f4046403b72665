#version 330 core
// Coloured triangles in world space: grid, arena, arrows, trails.
layout(location = 0) in vec2 aPosition;  // metres
layout(location = 1) in vec4 aColor;

uniform vec4 uTransform;  // clip = world * uTransform.xy + uTransform.zw

out vec4 vColor;

void main() {
    gl_Position = vec4(aPosition * uTransform.xy + uTransform.zw, 0.0, 1.0);
    vColor = aColor;
}

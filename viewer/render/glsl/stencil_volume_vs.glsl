//VTK::System::Dec
// The polygons as they are, w included: a vertex at infinity projects to its vanishing point.
in vec4 volumePosition;
uniform mat4 worldToClip;
void main() {
  gl_Position = worldToClip * volumePosition;
  gl_ClipDistance[0] = gl_Position.z + gl_Position.w;  // the near plane, which GL_DEPTH_CLAMP turns off
}

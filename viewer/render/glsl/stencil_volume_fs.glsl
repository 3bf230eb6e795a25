//VTK::System::Dec
// The volume writes no colour (the colour mask is off while it counts).
//VTK::Output::Dec
void main() { gl_FragData[0] = vec4(0.0); }

#version 450 core
// Writes nothing: drawn with an occlusion query where the resolve marked
// holes, it tells whether a frame has any before more references are
// warped to fill them.
void main() {}

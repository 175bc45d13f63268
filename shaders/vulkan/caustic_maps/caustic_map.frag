#version 460
// Caustic visibility map (paper 3.2, Figure 3): the objectId (instance index + 1; 0 = empty) of the
// surface nearest the light. The forward trace reads only this: it emits from the light through
// specular texels and finds the exact hit itself, so no position or normal target is written.
layout(location = 0) flat in uint inInstance;

layout(location = 0) out uint outObjectId;

void main() { outObjectId = inInstance + 1u; }

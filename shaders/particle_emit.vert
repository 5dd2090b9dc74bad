#version 450 core
// ParticleGeoUpdate, emission pass: one point per emission slot (no vertex
// data), each standing for up to kSlotSize newborn particles of one emitter.
flat out int vSlot;

void main() { vSlot = gl_VertexID; }

// What a full-screen pass or the sky gives a pack for the inputs only blocks have: full light, no
// block.properties id, a tangent along +x, the middle of the texture.

void tsol_readFlatInputs() {
  tsol_MultiTexCoord1 = vec4(vec2(PACK_LIGHT_SCALE), 0.0, 1.0);
  tsol_Entity = vec4(-1.0);
  tsol_MidTexCoord = vec4(0.5, 0.5, 0.0, 1.0);
  tsol_Tangent = vec4(1.0, 0.0, 0.0, 1.0);
  tsol_MidBlock = vec4(0.0);
  tsol_Velocity = vec4(0.0);
}

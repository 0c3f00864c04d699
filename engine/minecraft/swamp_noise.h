#pragma once
// Minecraft's biome information noise (Biome.BIOME_INFO_NOISE): one octave of 2D simplex noise from
// a Java random seeded with 2345. Swamps colour their grass by it: 0x4C763C where it is below -0.1 at
// (x, z) * 0.0225, else 0x6A7039, so swamp grass comes in patches tens of blocks across.

namespace terrasol {

// The noise at block column (x, z), about -1..1.
double swampGrassNoise(int x, int z);

}  // namespace terrasol

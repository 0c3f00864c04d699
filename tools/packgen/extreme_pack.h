#pragma once
// The test pack tests/packs/extreme_materials: LabPBR values at the ends of their ranges (smoothness 0
// and 255, F0 0, the metals, albedo metal, emission 254 and 255, normal maps with |xy| > 1 and lying in
// the surface, every channel 0), for the stability scenes in tests/scenes/extreme.

#include <filesystem>

namespace terrasol::packgen {

void writeExtremeMaterialsPack(const std::filesystem::path& dir);

}  // namespace terrasol::packgen

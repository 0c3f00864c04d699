#pragma once
// Where Terrasol's data lives, independent of the working directory.

#include <filesystem>
#include <optional>
#include <string>

namespace terrasol {

// The directory holding `shaders/` and `resourcepacks/`. Searched in order: $TERRASOL_DATA_DIR, the
// executable's directory and its parents (a build tree inside the source tree, or an install with
// the data beside the binary), then the source tree this binary was built from. Throws Error if none has
// both.
std::filesystem::path dataRoot();

std::filesystem::path shaderDir();        // dataRoot()/shaders
std::filesystem::path resourcePackDir();  // dataRoot()/resourcepacks
std::filesystem::path shaderPackDir();    // dataRoot()/shaderpacks: the shader packs shipped with the game

// Real third-party inputs for tests and benchmarks (packs, glTF samples), which the repository does
// not hold: $TERRASOL_TESTDATA when set, else `shared/testdata` beside the data root when it exists.
// `why` (when given) says what was looked for when there is none.
std::optional<std::filesystem::path> testDataDir(std::string* why = nullptr);

// Directory of the running executable (via /proc/self/exe).
std::filesystem::path executableDir();

}  // namespace terrasol

#include "core/paths.h"

#include <cstdlib>
#include <system_error>

#include "core/error.h"

namespace terrasol {
namespace fs = std::filesystem;

namespace {

bool isDataRoot(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "shaders", ec) && fs::is_directory(dir / "resourcepacks", ec);
}

fs::path findDataRoot() {
  if (const char* env = std::getenv("TERRASOL_DATA_DIR"); env && *env) {
    if (isDataRoot(env)) return fs::path(env);
    throw Error(std::string("TERRASOL_DATA_DIR=") + env + " has no shaders/ and resourcepacks/ directories");
  }
  for (fs::path dir = executableDir(); !dir.empty(); dir = dir.parent_path()) {
    if (isDataRoot(dir)) return dir;
    if (isDataRoot(dir / "share" / "terrasol")) return dir / "share" / "terrasol";
    if (dir == dir.parent_path()) break;
  }
  if (isDataRoot(TERRASOL_SOURCE_DIR)) return fs::path(TERRASOL_SOURCE_DIR);
  throw Error("cannot find Terrasol's data (shaders/ and resourcepacks/); set TERRASOL_DATA_DIR");
}

}  // namespace

fs::path executableDir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path();
}

fs::path dataRoot() {
  static const fs::path root = findDataRoot();  // constant for the life of the process
  return root;
}

std::optional<fs::path> testDataDir(std::string* why) {
  const char* env = std::getenv("TERRASOL_TESTDATA");
  const fs::path dir =
      env && *env ? fs::path(env) : (dataRoot() / ".." / "shared" / "testdata").lexically_normal();
  std::error_code error;
  if (fs::is_directory(dir, error)) return dir;
  if (why) {
    *why = env && *env
               ? "TERRASOL_TESTDATA (" + dir.string() + ") is not a directory"
               : "no third-party test data: " + dir.string() + " is absent and TERRASOL_TESTDATA is not set";
  }
  return std::nullopt;
}

fs::path shaderDir() {
  return dataRoot() / "shaders";
}
fs::path resourcePackDir() {
  return dataRoot() / "resourcepacks";
}

fs::path shaderPackDir() {
  return dataRoot() / "shaderpacks";
}

}  // namespace terrasol

#include "shader_pack_list.h"

#include <algorithm>
#include <set>
#include <system_error>

namespace terrasol {

std::vector<std::filesystem::path> findShaderPacks(const std::vector<std::filesystem::path>& dirs) {
  std::vector<std::filesystem::path> found;
  std::set<std::filesystem::path> seen;
  for (const std::filesystem::path& dir : dirs) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::filesystem::path& p = entry.path();
      const bool pack = (entry.is_directory(ec) && std::filesystem::is_directory(p / "shaders", ec)) ||
                        (entry.is_regular_file(ec) && p.extension() == ".zip");
      if (!pack) continue;
      const std::filesystem::path key = std::filesystem::weakly_canonical(p, ec);
      if (seen.insert(ec ? p : key).second) found.push_back(p);
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
  return found;
}

}  // namespace terrasol

// Runs a fuzz target over seeds and deterministic mutations of them (truncations, byte flips, header
// fields set to extremes), without libFuzzer, so every CI run exercises it. Texture seeds: the default
// pack's PNGs and animations, and the palette PNGs of the third-party test data when present; model
// seeds: the glTF samples there.
//   terrasol-fuzz-corpus [--ext=.gltf,.glb] SEED_DIR...   (default --ext=.png)

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void run(const std::string& input, long& count) {
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  ++count;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> seeds;
  std::string extensions = ".png";
  int first = 1;
  if (argc > 1 && std::string(argv[1]).starts_with("--ext=")) {
    extensions = std::string(argv[1]).substr(6);
    first = 2;
  }
  const bool textures = extensions == ".png";
  for (int i = first; i < argc; ++i) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i], ec)) {
      const auto path = entry.path();
      const std::string ext = path.extension().string();
      if (ext.empty() || ("," + extensions + ",").find("," + ext + ",") == std::string::npos ||
          seeds.size() > 60)
        continue;
      std::string seed = readFile(path);
      const auto meta = path.string() + ".mcmeta";
      if (std::filesystem::exists(meta)) seed += "\n--mcmeta--\n" + readFile(meta);
      seeds.push_back(std::move(seed));
    }
  }
  seeds.push_back("");
  if (textures) {
    seeds.push_back(
        "\n--mcmeta--\n{\"animation\": {\"frames\": [0, {\"index\": 99999999999}], \"frametime\": -1}}");
    seeds.push_back("\n--mcmeta--\n{\"animation\": {\"width\": 0, \"height\": 18446744073709551615}}");
  }
  long count = 0;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&] { return state = state * 6364136223846793005ull + 1442695040888963407ull; };
  for (const auto& seed : seeds) {
    run(seed, count);
    for (std::size_t cut = 0; cut < seed.size(); cut += std::max<std::size_t>(1, seed.size() / 24))
      run(seed.substr(0, cut), count);
    for (int i = 0; i < 48 && !seed.empty(); ++i) {
      std::string mutated = seed;
      for (int k = 0; k < 1 + static_cast<int>(next() % 4); ++k)
        mutated[next() % mutated.size()] = static_cast<char>(next());
      run(mutated, count);
    }
    if (textures && seed.size() > 24) {  // the IHDR width and height fields set to extremes
      for (const char fill : {'\x00', '\x7f', '\xff'}) {
        std::string mutated = seed;
        for (int k = 16; k < 24; ++k) mutated[static_cast<std::size_t>(k)] = fill;
        run(mutated, count);
      }
    }
  }
  std::printf("%ld inputs from %zu seeds, no crash\n", count, seeds.size());
  return 0;
}

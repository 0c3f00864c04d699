// Runs a fuzz target over seeds and deterministic mutations of them (truncations, byte flips, header
// fields set to extremes), without libFuzzer, so every CI run exercises it. Texture seeds: the default
// pack's PNGs and animations, and the palette PNGs of the third-party test data when present; model
// seeds: the glTF samples there; chunk seeds (--ext=.mca): the first chunks of Minecraft region files,
// each as its region holds it (the compression type byte, then the data).
//   terrasol-fuzz-corpus [--ext=.gltf,.glb | --ext=.mca] SEED_DIR...   (default --ext=.png)

#include <cstdint>
#include <cstdio>
#ifdef TERRASOL_INFLATE_CHUNK_SEEDS
#include <zlib.h>
#endif
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

// A region file's first few chunks: each its type byte and data, as the sectors hold them.
void addChunkSeeds(const std::string& region, std::vector<std::string>& seeds) {
  const auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(region[i]));
  };
  int taken = 0;
  for (std::size_t slot = 0; slot < 1024 && taken < 4 && region.size() >= 8192; ++slot) {
    const std::uint32_t location = byte(slot * 4) << 24 | byte(slot * 4 + 1) << 16 | byte(slot * 4 + 2) << 8;
    const std::size_t offset = static_cast<std::size_t>(location >> 8) * 4096;
    if (offset < 8192 || offset + 5 > region.size()) continue;
    const std::uint32_t length =
        byte(offset) << 24 | byte(offset + 1) << 16 | byte(offset + 2) << 8 | byte(offset + 3);
    if (length == 0 || offset + 4 + length > region.size()) continue;
    seeds.push_back(region.substr(offset + 4, length));
    ++taken;
#ifdef TERRASOL_INFLATE_CHUNK_SEEDS
    // The same chunk uncompressed (type 3), so mutations reach the NBT parser and the decoder.
    if (seeds.back()[0] == 2) {
      std::string raw(1u << 20, '\0');
      uLongf rawSize = raw.size();
      const std::string& packed = seeds.back();
      if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawSize,
                     reinterpret_cast<const Bytef*>(packed.data() + 1), packed.size() - 1) == Z_OK) {
        std::string plain(1, '\x03');
        plain.append(raw, 0, rawSize);
        seeds.push_back(std::move(plain));
      }
    }
#endif
  }
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
      if (ext == ".mca") {
        addChunkSeeds(seed, seeds);
        continue;
      }
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

// terrasol-soundgen PACK: writes the default pack's sounds (assets/minecraft/sounds/ and
// sounds.json) into the pack folder PACK. Run by hand when a recipe changes; the files are committed.
// terrasol-soundgen --look SHEET.png FILE.ogg...: the files' spectrograms, one under another, to
// look at what a recipe makes.

#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "soundgen.h"
#include "spectrogram.h"

namespace {

int look(int argc, char** argv) {
  using namespace terrasol;
  std::vector<Pcm> sounds;
  double longest = 0.0;
  for (int i = 3; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    sounds.push_back(decodeOgg({std::istreambuf_iterator<char>(in), {}}, argv[i]));
    longest = std::max(longest, static_cast<double>(sounds.back().frames()) / sounds.back().rate);
    std::printf("%2d %-60s %.2f s\n", i - 3, argv[i],
                static_cast<double>(sounds.back().frames()) / sounds.back().rate);
  }
  std::vector<Image> bands;
  for (const Pcm& p : sounds) bands.push_back(soundgen::spectrogram(p, 480, 88, longest));
  saveImage(argv[2], soundgen::stack(bands));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace terrasol::soundgen;
  if (argc >= 4 && std::string(argv[1]) == "--look") return look(argc, argv);
  if (argc != 2) {
    std::fprintf(stderr,
                 "usage: terrasol-soundgen PACK_DIR (resourcepacks/default)\n"
                 "       terrasol-soundgen --look SHEET.png FILE.ogg...\n");
    return 2;
  }
  try {
    Catalogue c;
    blockSounds(c);
    worldSounds(c);
    music(c);
    writeSounds(c, argv[1]);
    std::printf("wrote %zu sounds and %zu events\n", c.files.size(), c.events.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "terrasol-soundgen: %s\n", e.what());
    return 1;
  }
  return 0;
}

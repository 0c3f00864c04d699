#pragma once
// --benchmark: a flight over a throwaway world (a circle round the spawn, or a scene file's camera
// path), timed frame by frame until each is on screen, then once more with every pass timed.

#include <filesystem>

#include "options.h"

namespace terrasol {

class Game;

// A fresh temporary folder for the benchmark's world (deleted with it).
std::filesystem::path benchmarkWorldDir();

// Flies and prints the figures (and writes --benchmark-json). Returns the exit code.
int runBenchmark(Game& game, const GameOptions& options);

}  // namespace terrasol

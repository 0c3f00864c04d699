#pragma once
// The playable game in a window: input, physics ticks, block editing, streaming, drawing, HUD, saves,
// scripted runs and the benchmark flight.

#include "options.h"

namespace terrasol {

class GlfwWindow;

// Plays until the window closes, the menu's quit, a script's "quit" or --frames. Returns the exit code.
int playGame(GlfwWindow& window, const GameOptions& options);

}  // namespace terrasol

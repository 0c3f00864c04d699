#pragma once
// Plays an input script (--input-script) into the game: from the first frame the world round the
// player is ready (as a player waits for it to load), each frame the events due by the script's clock
// go to the Controls as a person's would, and its commands come back for the game to carry out.

#include <vector>

#include "input_router.h"
#include "input_script.h"
#include "player.h"

namespace terrasol {

class ScriptDriver {
 public:
  explicit ScriptDriver(InputScript script) : player_(std::move(script)) {}

  double step() const { return player_.step(); }
  // Starts the script once `worldReady`; true from then on.
  bool startIf(bool worldReady) { return started_ = started_ || worldReady; }
  bool started() const { return started_; }
  // One frame of `dt` seconds: lets go of last frame's taps, plays the events now due into `input`
  // (a look turns `player`) and returns the commands among them.
  std::vector<ScriptEvent> play(double dt, InputRouter& input, Player& player);

 private:
  ScriptPlayer player_;
  bool started_ = false;
  double clock_ = 0.0;        // script time: from the start
  std::vector<int> keyTaps_;  // tapped this frame: released the next
  std::vector<MouseButton> buttonTaps_;
};

}  // namespace terrasol

#include "game.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <random>

#include "benchmark.h"
#include "core/log.h"
#include "core/paths.h"
#include "first_run.h"
#include "platform/glfw/glfw_window.h"
#include "scene/block_colours.h"
#include "world_choice.h"

// The game's parts made and wired together, and what the menu and the script ask of them.

namespace terrasol {
namespace {

SettingsFile settingsFor(const GameOptions& options) {
  SettingsFile file;
  file.path = options.settings.empty() ? defaultSettingsFile() : options.settings;
  file.values = loadSettings(file.path);
  if (!options.packs.empty()) {
    file.values.packs.clear();
    for (const auto& p : options.packs) file.values.packs.push_back({std::filesystem::absolute(p), true});
  }
  if (!options.shaderpack.empty()) file.values.shaderpack = std::filesystem::absolute(options.shaderpack);
  return file;
}

std::uint64_t seedOf(const GameOptions& options) {
  if (options.benchmark) return options.seed.value_or(1);
  return options.seed ? *options.seed : std::random_device{}();
}

// The folder played, and the Minecraft save under it: an overlay among the game's worlds when --world
// names a Minecraft save.
WorldChoice worldOf(const GameOptions& options) {
  if (options.benchmark) return {benchmarkWorldDir(), {}};
  return chooseWorld(options.world, kWorldsDir);
}

constexpr double kNoticeSeconds = 10.0;

std::string firstOf(const std::vector<std::string>& names) {
  return names.empty() ? std::string() : names.front();
}

}  // namespace

Game::Game(GlfwWindow& window, const GameOptions& options)
    : window_(window),
      options_(options),
      settings_(settingsFor(options)),
      content_(BlockAssets::registry(settings_.values.packs)),
      renderer_(content_.blocks, settings_.values, content_.defaultBake ? &*content_.defaultBake : nullptr),
      world_(worldOf(options).dir, options.benchmark.has_value(), seedOf(options), options.seed, content_,
             renderer_, settings_.values.viewDistance, worldOf(options).minecraft),
      interaction_(content_),
      input_(window, settings_.values.keys),
      ui_(window.handle(), settings_, firstOf(world_.propFiles())),
      overlay_(reinterpret_cast<const char*>(glGetString(GL_RENDERER))),
      audio_(options, content_.blocks) {
  content_.defaultBake.reset();  // the shapes and the first atlas are made
  audio_.setPacks(renderer_.assets().packs);
  audio_.setVolumes(settings_.values.sound);
  interaction_.setSurvivalDigging(settings_.values.survivalDigging);
  ui_.setSoundDevice(audio_.deviceLine());
  if (!options.inputScript.empty()) script_.emplace(loadInputScript(options.inputScript));
  input_.setScreenKeys(&ui_);
  if (!world_.notice().empty()) ui_.showNotice(world_.notice(), frames_.clock, kNoticeSeconds);
  if (!std::filesystem::exists(settings_.path)) probeMachine();
  resetFarTerrain();
  window_.setVsync(settings_.values.vsync && !options.benchmark);
  input_.show(Screen::None);
}

float Game::renderScale() const {
  const GameSettings& s = settings_.values;
  return s.targetFps > 0 ? frames_.resolution.scale() : s.renderScale;
}

glm::ivec2 Game::drawableSize() const {
  return window_.minimised() ? glm::ivec2(0) : window_.framebufferSize();
}

void Game::probeMachine() {
  if (drawableSize().x <= 0 || drawableSize().y <= 0) return;
  std::vector<double> ms;
  for (int i = 0; i < 7; ++i) {
    const Clock::time_point start = Clock::now();
    draw(false);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  ms.erase(ms.begin());  // the first pays for shader and target creation
  std::sort(ms.begin(), ms.end());
  GameSettings& s = settings_.values;
  s = firstRunSettings({overlay_.glRenderer(), ms[ms.size() / 2]}, s);
  renderer_.applySettings(s);
  world_.streamed().setViewDistance(s.viewDistance);
  frames_.resolution.setMaxScale(s.renderScale);
  logInfo("first start: " + s.firstRun->choice);
  if (!options_.benchmark) settings_.save();
}

void Game::runCommand(const ScriptEvent& command) {
  switch (command.command) {
    case ScriptCommand::Save:
      save();
      break;
    case ScriptCommand::Screenshot:
      frames_.screenshot = true;
      break;
    case ScriptCommand::Quit:
      frames_.quit = true;
      break;
    case ScriptCommand::Minimise:
      window_.minimise();
      break;
    case ScriptCommand::Restore:
      window_.restore();
      break;
    case ScriptCommand::PlaceProp:
      interaction_.placeProp(command.model, world_);
      break;
  }
}

void Game::applyMenu(const MenuResult& r) {
  const GameSettings& s = settings_.values;
  if (r.viewChanged) {
    world_.streamed().setViewDistance(s.viewDistance);
    resetFarTerrain();
  }
  if (r.rendererChanged) renderer_.applySettings(s);
  if (r.packsChanged) reloadPacks();
  if (r.shaderPackChanged) renderer_.setShaderPack(s.shaderpack);
  if (r.soundChanged) audio_.setVolumes(s.sound);
  if (r.settingsChanged) {
    window_.setVsync(s.vsync);
    interaction_.setSurvivalDigging(s.survivalDigging);
    settings_.save();
  }
  if (r.save) save();
  if (r.resume) input_.show(Screen::None);
  if (r.quit) frames_.quit = true;
}

void Game::reloadPacks() {
  try {
    std::unique_ptr<BlockAssets> assets = renderer_.loadPacks(settings_.values.packs);
    world_.streamed().remeshAll(assets->table);
    renderer_.commit(std::move(assets));
    audio_.setPacks(renderer_.assets().packs);
    resetFarTerrain();
    for (const PackProblem& p : renderer_.assets().atlas.problems) logWarning(p.message);
  } catch (const Error& e) {
    logError(std::string("packs not reloaded: ") + e.what());  // the old ones stay
  }
}

void Game::resetFarTerrain() {
  const GameSettings& s = settings_.values;
  far_.reset();  // its workers stop before a new one starts
  renderer_.lod().clear();
  far_ = FarTerrain::create(s.lod, world_, lodPaletteOf(content_.blocks, renderer_.assets().atlas));
}

void Game::save() {
  world_.save();
  frames_.sinceSave = 0.0;
}

int playGame(GlfwWindow& window, const GameOptions& options) {
  Game game(window, options);
  return game.run();
}

}  // namespace terrasol

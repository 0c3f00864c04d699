#include "assets/sound_events.h"

#include <algorithm>
#include <exception>

#include "core/error.h"
#include "core/json_check.h"

namespace terrasol {
namespace {

using namespace json_check;

constexpr int kMaxEventDepth = 8;  // events naming events: deeper is a loop

// Minecraft's rules: names are namespaced, "minecraft:" when none is given.
std::string namespaced(std::string_view name) {
  return name.find(':') == std::string_view::npos ? join({"minecraft:", name}) : std::string(name);
}

SoundEntry entryOf(const json& value, const std::string& key) {
  SoundEntry e;
  if (value.is_string()) {
    e.name = namespaced(nonEmptyString(value, key));
    return e;
  }
  checkObject(value, key,
              {"name", "type", "volume", "pitch", "weight", "stream", "attenuation_distance", "preload"});
  e.name = namespaced(nonEmptyString(required(value, key, "name"), member(key, "name")));
  if (const json* v = field(value, "type")) {
    static constexpr std::string_view kTypes[] = {"file", "event"};
    e.event = oneOf(*v, member(key, "type"), kTypes) == "event";
  }
  if (const json* v = field(value, "volume")) e.volume = numberIn(*v, member(key, "volume"), 0.0, 1e3, false);
  if (const json* v = field(value, "pitch")) e.pitch = numberIn(*v, member(key, "pitch"), 0.0, 1e3, true);
  if (const json* v = field(value, "weight"))
    e.weight = static_cast<int>(wholeNumber(*v, member(key, "weight"), 0, 1 << 20));
  if (const json* v = field(value, "stream")) e.stream = boolean(*v, member(key, "stream"));
  if (const json* v = field(value, "attenuation_distance"))
    e.reach = numberIn(*v, member(key, "attenuation_distance"), 0.0, 1e6, true);
  if (const json* v = field(value, "preload")) boolean(*v, member(key, "preload"));
  return e;
}

}  // namespace

std::string soundFile(std::string_view name) {
  const std::string full = namespaced(name);
  const std::size_t colon = full.find(':');
  return join({"assets/", std::string_view(full).substr(0, colon), "/sounds/",
               std::string_view(full).substr(colon + 1), ".ogg"});
}

SoundEvents SoundEvents::load(const PackStack& packs, std::vector<std::string>& problems) {
  SoundEvents events;
  for (const auto& pack : packs.packs()) {
    const std::string path = "assets/minecraft/sounds.json";
    const std::string file = pack->files().displayName(path);
    try {
      const std::optional<std::vector<std::uint8_t>> bytes = pack->files().read(path);
      if (!bytes) continue;
      events.merge(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()), file,
                   problems);
    } catch (const std::exception& e) {
      problems.push_back(e.what());  // unreadable or too large: PackSource names the file
    }
  }
  return events;
}

void SoundEvents::merge(std::string_view text, const std::string& file, std::vector<std::string>& problems) {
  json root;
  try {
    root = parseJson(text, file);  // its errors name the file, line and column
  } catch (const std::exception& e) {
    problems.push_back(e.what());
    return;
  }
  if (!root.is_object()) {
    problems.push_back(withFile(file, "expected an object of sound events"));
    return;
  }
  for (const auto& [name, value] : root.items()) {
    // An event whose own keys are wrong is left out whole; a bad sound in its list, alone.
    SoundEvent parsed;
    bool replace = false;
    try {
      checkObject(value, name, {"sounds", "replace", "subtitle"});
      if (const json* v = field(value, "replace")) replace = boolean(*v, member(name, "replace"));
      if (const json* v = field(value, "subtitle"))
        parsed.subtitle = nonEmptyString(*v, member(name, "subtitle"));
      if (const json* v = field(value, "sounds")) {
        if (!v->is_array()) expected(member(name, "sounds"), "a list of sounds", *v);
        for (std::size_t i = 0; i < v->size(); ++i) {
          try {
            parsed.sounds.push_back(entryOf((*v)[i], element(member(name, "sounds"), i)));
          } catch (const Error& e) {
            problems.push_back(withFile(file, e.what()));
          }
        }
      }
    } catch (const Error& e) {
      problems.push_back(withFile(file, e.what()));
      continue;
    }
    SoundEvent& event = events_[name];
    if (replace) event.sounds.clear();
    event.sounds.insert(event.sounds.end(), parsed.sounds.begin(), parsed.sounds.end());
    if (parsed.subtitle) event.subtitle = parsed.subtitle;
  }
}

const SoundEvent* SoundEvents::find(std::string_view event) const {
  const auto it = events_.find(event);
  return it == events_.end() ? nullptr : &it->second;
}

std::optional<SoundPick> SoundEvents::pick(std::string_view event, std::uint32_t random) const {
  SoundPick out;
  std::string name(event);
  for (int depth = 0; depth < kMaxEventDepth; ++depth) {
    const SoundEvent* e = find(name);
    if (!e) return std::nullopt;
    std::uint64_t total = 0;
    for (const SoundEntry& s : e->sounds) total += static_cast<std::uint64_t>(s.weight);
    if (total == 0) return std::nullopt;
    std::uint64_t at = random % total;
    random = random * 747796405u + 2891336453u;  // a fresh draw for a nested event (PCG's step)
    const SoundEntry* chosen = nullptr;
    for (const SoundEntry& s : e->sounds) {
      if (at < static_cast<std::uint64_t>(s.weight)) {
        chosen = &s;
        break;
      }
      at -= static_cast<std::uint64_t>(s.weight);
    }
    out.volume *= chosen->volume;
    out.pitch *= chosen->pitch;
    if (!chosen->event) {
      out.file = soundFile(chosen->name);
      out.stream = chosen->stream;
      out.reach = chosen->reach;
      return out;
    }
    // An event names another by its bare name ("minecraft:block.stone.break" or "block.stone.break").
    const std::size_t colon = chosen->name.find(':');
    name = chosen->name.substr(colon + 1);
  }
  return std::nullopt;  // events that name each other round
}

std::vector<std::string> SoundEvents::files(std::string_view event, bool streamed) const {
  std::vector<std::string> out;
  std::vector<std::pair<std::string, int>> toVisit = {{std::string(event), 0}};
  while (!toVisit.empty()) {
    const auto [name, depth] = toVisit.back();
    toVisit.pop_back();
    const SoundEvent* e = depth < kMaxEventDepth ? find(name) : nullptr;
    if (!e) continue;
    for (const SoundEntry& s : e->sounds) {
      if (s.event) {
        toVisit.emplace_back(s.name.substr(s.name.find(':') + 1), depth + 1);
      } else if (streamed || !s.stream) {
        out.push_back(soundFile(s.name));
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace terrasol

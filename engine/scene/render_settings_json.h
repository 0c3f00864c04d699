#pragma once
// The render settings' JSON objects, as scene files ("render.shadow", ...) and the game's settings file
// write them: each read over a settings value at key path `key` (errors name it, json_check's way),
// and written back whole.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "core/render_settings.h"

namespace terrasol {

// A "render.shadow" object (also the game's settings) at key path `key`, over `shadow`'s values; and back.
void parseShadow(const nlohmann::json& value, const std::string& key, ShadowSettings& shadow);
nlohmann::json shadowJson(const ShadowSettings& shadow);
// A "render.reflections" object at key path `key`, over `reflections`' values.
void parseReflections(const nlohmann::json& value, const std::string& key, ReflectionSettings& reflections);
nlohmann::json reflectionsJson(const ReflectionSettings& reflections);
// "render.bloom", "render.clouds", "render.fog" and "render.shafts", the same way.
void parseBloom(const nlohmann::json& value, const std::string& key, BloomSettings& bloom);
nlohmann::json bloomJson(const BloomSettings& bloom);
void parseClouds(const nlohmann::json& value, const std::string& key, CloudSettings& clouds);
nlohmann::json cloudsJson(const CloudSettings& clouds);
void parseLod(const nlohmann::json& value, const std::string& key, LodSettings& lod);
nlohmann::json lodJson(const LodSettings& lod);
void parseFog(const nlohmann::json& value, const std::string& key, FogSettings& fog);
nlohmann::json fogJson(const FogSettings& fog);
void parseShafts(const nlohmann::json& value, const std::string& key, ShaftSettings& shafts);
nlohmann::json shaftsJson(const ShaftSettings& shafts);

}  // namespace terrasol

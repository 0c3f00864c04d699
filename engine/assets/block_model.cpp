#include "assets/block_model.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "assets/resource_pack.h"
#include "core/error.h"
#include "core/json_check.h"
#include "core/log.h"
#include "core/model_units.h"

namespace terrasol {

using namespace json_check;

namespace {

constexpr int kMaxModelDepth = 64;  // parents; references between textures ("#a" -> "#b") likewise

ModelFace faceOf(const json& value, const std::string& key) {
  // Minecraft also accepts "bottom" for down in cullface.
  if (value.is_string() && value.get<std::string>() == "bottom") return ModelFace::Down;
  return enumOf(value, key, kModelFaceNames);
}

glm::vec3 boxCorner(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 3) expected(key, "an array of 3 numbers from -16 to 32", value);
  glm::vec3 v;
  for (std::size_t i = 0; i < 3; ++i)
    v[static_cast<int>(i)] =
        numberIn(value[i], element(key, i), -kModelUnits, 2 * kModelUnits, false);  // -1..2 blocks
  return v;
}

// Minecraft's default uv of a face: the element's extent on the face, seen from outside.
glm::vec4 defaultUv(ModelFace face, glm::vec3 from, glm::vec3 to) {
  constexpr float kUnits = kModelUnits;
  switch (face) {
    case ModelFace::Down:
      return {from.x, kUnits - to.z, to.x, kUnits - from.z};
    case ModelFace::Up:
      return {from.x, from.z, to.x, to.z};
    case ModelFace::North:
      return {kUnits - to.x, kUnits - to.y, kUnits - from.x, kUnits - from.y};
    case ModelFace::South:
      return {from.x, kUnits - to.y, to.x, kUnits - from.y};
    case ModelFace::West:
      return {from.z, kUnits - to.y, to.z, kUnits - from.y};
    case ModelFace::East:
      return {kUnits - to.z, kUnits - to.y, kUnits - from.z, kUnits - from.y};
  }
  return {0.0f, 0.0f, kUnits, kUnits};
}

ElementFace readFace(const json& value, const std::string& key, ModelFace face, const ModelElement& e) {
  if (!value.is_object()) expected(key, "an object", value);
  ElementFace f;
  f.uv = defaultUv(face, e.from, e.to);
  if (const json* uv = field(value, "uv")) {
    const std::string k = member(key, "uv");
    if (!uv->is_array() || uv->size() != 4) expected(k, "an array of 4 numbers from 0 to 16", *uv);
    for (std::size_t i = 0; i < 4; ++i)
      f.uv[static_cast<int>(i)] = numberIn((*uv)[i], element(k, i), 0.0, kModelUnits, false);
  }
  const json* texture = field(value, "texture");
  if (!texture) fail(key, "a face needs a \"texture\"");
  f.texture = nonEmptyString(*texture, member(key, "texture"));
  if (const json* c = field(value, "cullface")) f.cullface = faceOf(*c, member(key, "cullface"));
  if (const json* r = field(value, "rotation")) {
    f.rotation = static_cast<int>(wholeNumber(*r, member(key, "rotation"), 0, 270));
    if (f.rotation % 90 != 0) expected(member(key, "rotation"), "0, 90, 180 or 270", *r);
  }
  if (const json* t = field(value, "tintindex"))
    f.tintIndex = static_cast<int>(wholeNumber(*t, member(key, "tintindex"), -1, 1 << 20));
  return f;
}

ElementRotation readRotation(const json& value, const std::string& key) {
  if (!value.is_object()) expected(key, "an object", value);
  ElementRotation r;
  if (const json* o = field(value, "origin")) r.origin = boxCorner(*o, member(key, "origin"));
  const json* axis = field(value, "axis");
  if (!axis) fail(key, "a rotation needs an \"axis\"");
  static constexpr std::string_view kAxes[] = {"x", "y", "z"};
  r.axis = static_cast<int>(
      std::find(std::begin(kAxes), std::end(kAxes), oneOf(*axis, member(key, "axis"), kAxes)) -
      std::begin(kAxes));
  const json* angle = field(value, "angle");
  if (!angle) fail(key, "a rotation needs an \"angle\"");
  r.angle = static_cast<float>(finiteNumber(*angle, member(key, "angle")));
  if (r.angle != 0.0f && std::abs(r.angle) != 22.5f && std::abs(r.angle) != 45.0f) {
    expected(member(key, "angle"), "-45, -22.5, 0, 22.5 or 45", *angle);
  }
  if (const json* s = field(value, "rescale")) r.rescale = boolean(*s, member(key, "rescale"));
  return r;
}

ModelElement readElement(const json& value, const std::string& key) {
  if (!value.is_object()) expected(key, "an object", value);
  ModelElement e;
  const json* from = field(value, "from");
  const json* to = field(value, "to");
  if (!from || !to) fail(key, "an element needs \"from\" and \"to\"");
  e.from = boxCorner(*from, member(key, "from"));
  e.to = boxCorner(*to, member(key, "to"));
  for (int i = 0; i < 3; ++i) {
    if (e.from[i] > e.to[i]) fail(key, "\"from\" must not exceed \"to\" on any axis");
  }
  if (const json* r = field(value, "rotation")) e.rotation = readRotation(*r, member(key, "rotation"));
  if (const json* s = field(value, "shade")) e.shade = boolean(*s, member(key, "shade"));
  if (const json* faces = field(value, "faces")) {
    const std::string k = member(key, "faces");
    if (!faces->is_object()) expected(k, "an object", *faces);
    for (const auto& [name, face] : faces->items()) {
      const ModelFace f = faceOf(json(name), member(k, name));
      e.faces[static_cast<std::size_t>(f)] = readFace(face, member(k, name), f, e);
    }
  }
  return e;
}

}  // namespace

glm::vec3 faceNormal(ModelFace face) {
  static constexpr glm::vec3 kNormals[] = {{0, -1, 0}, {0, 1, 0},  {0, 0, -1},
                                           {0, 0, 1},  {-1, 0, 0}, {1, 0, 0}};
  return kNormals[static_cast<int>(face)];
}

std::string resourceName(const std::string& location) {
  const std::size_t colon = location.find(':');
  return colon == std::string::npos ? location : location.substr(colon + 1);
}

const ModelLibrary::Raw& ModelLibrary::raw(const std::string& name) {
  if (const auto it = raws_.find(name); it != raws_.end()) return it->second;
  const std::string path = "assets/minecraft/models/" + name + ".json";
  const auto found = packs_.find(path);
  if (!found) throw Error(join({"no pack has the model ", name, " (", path, ")"}));
  const std::string file = found->pack->files().displayName(path);
  const std::vector<std::uint8_t> bytes = found->pack->files().require(path);
  const json root =
      parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file);
  Raw r;
  r.file = file;
  try {
    // Unknown keys (display, gui_light, an editor's notes) are Minecraft's or a tool's, not errors.
    if (!root.is_object()) expected("", "a JSON object", root);
    if (const json* p = field(root, "parent")) r.parent = resourceName(nonEmptyString(*p, "parent"));
    if (const json* t = field(root, "textures")) {
      if (!t->is_object()) expected("textures", "an object", *t);
      for (const auto& [key, value] : t->items())
        r.textures[key] = nonEmptyString(value, member("textures", key));
    }
    if (const json* a = field(root, "ambientocclusion")) r.ambientOcclusion = boolean(*a, "ambientocclusion");
    if (const json* es = field(root, "elements")) {
      if (!es->is_array()) expected("elements", "an array", *es);
      r.elements.emplace();
      for (std::size_t i = 0; i < es->size(); ++i)
        r.elements->push_back(readElement((*es)[i], element("elements", i)));
    }
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
  return raws_.emplace(name, std::move(r)).first->second;
}

// "#side" through the chain's texture maps (child first) to a texture name, or kMissingTexture.
std::string ModelLibrary::resolveTexture(const std::vector<const Raw*>& chain, const std::string& reference) {
  std::string ref = reference;
  for (int depth = 0; depth < kMaxModelDepth && !ref.empty() && ref[0] == '#'; ++depth) {
    const std::string key = ref.substr(1);
    std::optional<std::string> next;
    for (const Raw* r : chain) {
      if (const auto it = r->textures.find(key); it != r->textures.end()) {
        next = it->second;
        break;
      }
    }
    if (!next) {
      ref.clear();
      break;
    }
    ref = *next;
  }
  if (ref.empty() || ref[0] == '#') {
    if (missing_.insert(chain.front()->file + ": " + reference).second) {
      logWarning(join({chain.front()->file, ": texture ", reference, " is not defined: drawn as missing"}));
    }
    return kMissingTexture;
  }
  return resourceName(ref);
}

const BlockModel& ModelLibrary::model(const std::string& location) {
  const std::string name = resourceName(location);
  if (const auto it = models_.find(name); it != models_.end()) return it->second;
  std::vector<const Raw*> chain;  // the model, then its parents
  std::vector<std::string> names;
  for (std::string n = name; !n.empty();) {
    if (std::find(names.begin(), names.end(), n) != names.end() || names.size() >= kMaxModelDepth) {
      names.push_back(n);
      std::string path;
      for (const std::string& m : names) path += (path.empty() ? "" : " -> ") + m;
      throw Error(join({raw(name).file, ": parent cycle: ", path}));
    }
    names.push_back(n);
    try {
      chain.push_back(&raw(n));
    } catch (const Error& e) {
      if (names.size() == 1) throw;
      std::string path;
      for (const std::string& m : names) path += (path.empty() ? "" : " -> ") + m;
      throw Error(join({chain.front()->file, ": parent chain ", path, ": ", e.what()}));
    }
    n = chain.back()->parent;
  }
  BlockModel m;
  m.name = name;
  for (const Raw* r : chain) {
    if (r->ambientOcclusion) {
      m.ambientOcclusion = *r->ambientOcclusion;
      break;
    }
  }
  for (const Raw* r : chain) {
    if (!r->elements) continue;
    m.elements = *r->elements;
    break;
  }
  for (ModelElement& e : m.elements) {
    for (std::optional<ElementFace>& f : e.faces) {
      if (f) f->texture = resolveTexture(chain, f->texture);
    }
  }
  return models_.emplace(name, std::move(m)).first->second;
}

}  // namespace terrasol

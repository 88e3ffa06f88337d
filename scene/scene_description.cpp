#include "scene/scene_description.h"

#include "core/image/color.h"
#include "core/io/json_fields.h"
#include "scene/mesh_builder.h"
#include "scene/procedural_texture.h"

#include <cstdlib>
#include <map>

namespace triwalk {

namespace {

glm::vec3 srgbToLinear(glm::vec3 c) { return {triwalk::srgbToLinear(c.r), triwalk::srgbToLinear(c.g), triwalk::srgbToLinear(c.b)}; }

struct MaterialEntry {
  int index = 0;
  float textureSize = 1.0f;  // metres per texture repeat
};

class SceneDescriptionReader {
public:
  SceneDescriptionReader(const nlohmann::json& document, std::string file) : root_(document, std::move(file)) {}

  Scene read() {
    scene_.name = root_.stringOr("name", "scene");
    readArea();
    readLighting();
    readMaterials();
    const nlohmann::json& objects = root_.array("objects");
    for (size_t i = 0; i < objects.size(); ++i) readObject(root_.element("objects", i));
    for (auto& [name, builder] : builders_) {
      if (!builder.empty()) scene_.meshes.push_back(builder.take());
    }
    if (scene_.meshes.empty()) root_.fail("the scene has no geometry");
    return std::move(scene_);
  }

private:
  void readArea() {
    const JsonObject area = root_.object("walkable_area");
    scene_.walkableArea.min = area.vec2("min");
    scene_.walkableArea.max = area.vec2("max");
    scene_.walkableArea.eyeHeight = float(area.numberOr("eye_height", 1.6));
    scene_.walkableArea.floorHeight = float(area.numberOr("floor_height", 0.0));
    if (!(scene_.walkableArea.max.x > scene_.walkableArea.min.x && scene_.walkableArea.max.y > scene_.walkableArea.min.y)) {
      area.fail("max must exceed min in x and y");
    }
  }

  void readLighting() {
    scene_.ambient = root_.vec3Or("ambient", scene_.ambient);
    if (root_.has("sky")) {
      const JsonObject sky = root_.object("sky");
      scene_.sky.zenith = sky.vec3Or("zenith", scene_.sky.zenith);
      scene_.sky.horizon = sky.vec3Or("horizon", scene_.sky.horizon);
      scene_.sky.ground = sky.vec3Or("ground", scene_.sky.ground);
      scene_.sky.sunDirection = glm::normalize(sky.vec3Or("sun_direction", scene_.sky.sunDirection));
      scene_.sky.sunColor = sky.vec3Or("sun_color", scene_.sky.sunColor);
    }
    if (root_.has("lights")) {
      for (size_t i = 0; i < root_.array("lights").size(); ++i) {
        const JsonObject light = root_.element("lights", i);
        scene_.lights.push_back({light.vec3("position"), light.vec3("color"), float(light.numberOr("range", 5.0))});
      }
    }
  }

  void readMaterials() {
    const JsonObject materials = root_.object("materials");
    unsigned seed = 1;
    for (const auto& [name, value] : materials.json().items()) {
      const JsonObject entry = materials.object(name);
      SceneMaterial material;
      material.name = name;
      material.specular = float(entry.numberOr("specular", 0.0));
      material.shininess = float(entry.numberOr("shininess", 32.0));
      MaterialEntry record{int(scene_.materials.size()), float(entry.numberOr("texture_size", 1.0))};
      if (record.textureSize <= 0.0f) entry.fail("texture_size must be positive");
      if (entry.has("pattern")) {
        PatternSpec spec;
        const std::string pattern = entry.string("pattern");
        if (!parsePatternKind(pattern, spec.kind)) entry.fail("unknown pattern '" + pattern + "'");
        spec.primary = entry.vec3("primary");
        spec.secondary = entry.vec3Or("secondary", spec.primary * 0.6f);
        spec.repeats = entry.integerOr("repeats", spec.repeats);
        spec.variation = float(entry.numberOr("variation", spec.variation));
        spec.detail = float(entry.numberOr("detail", spec.detail));
        spec.resolution = entry.integerOr("resolution", spec.resolution);
        spec.seed = seed++;
        if (spec.repeats < 1 || spec.resolution < 16 || spec.resolution > 4096) {
          entry.fail("repeats must be >= 1 and resolution in [16, 4096]");
        }
        material.diffuseTexture = int(scene_.textures.size());
        scene_.textures.push_back(generatePatternTexture(spec, name));
      } else {
        material.baseColor = srgbToLinear(entry.vec3("color"));
      }
      scene_.materials.push_back(material);
      materialEntries_[name] = record;
    }
  }

  MeshBuilder& builderFor(const JsonObject& object) {
    const std::string name = object.string("material");
    auto entry = materialEntries_.find(name);
    if (entry == materialEntries_.end()) object.fail("unknown material '" + name + "'");
    auto builder = builders_.find(name);
    if (builder == builders_.end()) {
      builder = builders_.emplace(name, MeshBuilder(entry->second.index, entry->second.textureSize)).first;
    }
    return builder->second;
  }

  void readObject(const JsonObject& object) {
    const std::string type = object.string("type");
    MeshBuilder& builder = builderFor(object);
    const float cell = float(object.numberOr("cell_size", 0.5));
    if (cell <= 0.0f) object.fail("cell_size must be positive");
    if (type == "box") {
      const glm::vec3 lower = object.vec3("min"), upper = object.vec3("max");
      if (!glm::all(glm::lessThan(lower, upper))) object.fail("box min must be below max");
      builder.addBox(lower, upper, cell, lower.z <= scene_.walkableArea.floorHeight);
    } else if (type == "wall") {
      readWall(object, builder, cell);
    } else if (type == "floor" || type == "ceiling") {
      readSlab(object, builder, cell, type == "floor");
    } else if (type == "cylinder") {
      const float radius = float(object.number("radius"));
      const int segments = object.integerOr("segments", 32);
      if (radius <= 0.0f || segments < 3) object.fail("cylinder needs radius > 0 and segments >= 3");
      builder.addCylinder(object.vec2("center"), radius, float(object.number("bottom")), float(object.number("top")),
                          segments);
    } else if (type == "sphere") {
      const float radius = float(object.number("radius"));
      const int segments = object.integerOr("segments", 32);
      if (radius <= 0.0f || segments < 4) object.fail("sphere needs radius > 0 and segments >= 4");
      builder.addSphere(object.vec3("center"), radius, segments);
    } else {
      object.fail("unknown object type '" + type + "'");
    }
  }

  // A straight wall from one floor point to another, cut by openings
  // (doorways, windows) given as intervals along the wall and in height.
  void readWall(const JsonObject& object, MeshBuilder& builder, float cell) {
    const glm::vec2 from = object.vec2("from"), to = object.vec2("to");
    const float thickness = float(object.numberOr("thickness", 0.2));
    const float bottom = float(object.numberOr("bottom", 0.0)), top = float(object.number("top"));
    const float length = glm::length(to - from);
    if (length <= 0.0f || thickness <= 0.0f || top <= bottom) object.fail("wall needs length, thickness and height");
    const bool alongX = std::abs(to.y - from.y) < 1e-6f;
    const bool alongY = std::abs(to.x - from.x) < 1e-6f;
    if (!alongX && !alongY) object.fail("walls must be axis-aligned");

    struct Opening { float start, end, bottom, top; };
    std::vector<Opening> openings;
    if (object.has("openings")) {
      for (size_t i = 0; i < object.array("openings").size(); ++i) {
        const JsonObject opening = object.element("openings", i);
        Opening o{float(opening.number("start")), float(opening.number("end")),
                  float(opening.numberOr("bottom", bottom)), float(opening.number("top"))};
        if (!(o.start >= 0.0f && o.end <= length && o.start < o.end && o.bottom < o.top)) {
          opening.fail("opening must lie inside the wall");
        }
        openings.push_back(o);
      }
    }
    std::sort(openings.begin(), openings.end(), [](const Opening& a, const Opening& b) { return a.start < b.start; });

    const glm::vec2 direction = (to - from) / length;
    auto addPiece = [&](float start, float end, float pieceBottom, float pieceTop) {
      if (end - start <= 1e-5f || pieceTop - pieceBottom <= 1e-5f) return;
      const glm::vec2 a = from + direction * start, b = from + direction * end;
      const glm::vec2 half = alongX ? glm::vec2(0.0f, 0.5f * thickness) : glm::vec2(0.5f * thickness, 0.0f);
      const glm::vec2 lower = glm::min(a, b) - half, upper = glm::max(a, b) + half;
      builder.addBox({lower, pieceBottom}, {upper, pieceTop}, cell, pieceBottom <= scene_.walkableArea.floorHeight);
    };
    float cursor = 0.0f;
    for (const Opening& o : openings) {
      addPiece(cursor, o.start, bottom, top);
      addPiece(o.start, o.end, bottom, o.bottom);
      addPiece(o.start, o.end, o.top, top);
      cursor = o.end;
    }
    addPiece(cursor, length, bottom, top);
  }

  // A horizontal rectangle facing up (floor) or down (ceiling), with
  // rectangular holes (skylights) removed cell by cell.
  void readSlab(const JsonObject& object, MeshBuilder& builder, float cell, bool facingUp) {
    const glm::vec2 lower = object.vec2("min"), upper = object.vec2("max");
    const float z = float(object.number("z"));
    std::vector<glm::vec4> holes;
    if (object.has("holes")) {
      for (size_t i = 0; i < object.array("holes").size(); ++i) {
        const JsonObject hole = object.element("holes", i);
        holes.push_back(glm::vec4(hole.vec2("min"), hole.vec2("max")));
      }
    }
    const int cellsX = std::max(1, int(std::round((upper.x - lower.x) / cell)));
    const int cellsY = std::max(1, int(std::round((upper.y - lower.y) / cell)));
    const float stepX = (upper.x - lower.x) / float(cellsX), stepY = (upper.y - lower.y) / float(cellsY);
    for (int j = 0; j < cellsY; ++j) {
      for (int i = 0; i < cellsX; ++i) {
        const glm::vec2 c = lower + glm::vec2((float(i) + 0.5f) * stepX, (float(j) + 0.5f) * stepY);
        bool inHole = false;
        for (const glm::vec4& h : holes) inHole |= c.x > h.x && c.x < h.z && c.y > h.y && c.y < h.w;
        if (inHole) continue;
        const glm::vec3 origin(lower.x + float(i) * stepX, lower.y + float(j) * stepY, z);
        if (facingUp) {
          builder.addQuad(origin, {stepX, 0, 0}, {0, stepY, 0}, cell);
        } else {
          builder.addQuad(origin, {0, stepY, 0}, {stepX, 0, 0}, cell);
        }
      }
    }
  }

  JsonObject root_;
  Scene scene_;
  std::map<std::string, MaterialEntry> materialEntries_;
  std::map<std::string, MeshBuilder> builders_;
};

}  // namespace

Scene loadSceneDescription(const std::filesystem::path& path) {
  return sceneFromDescription(readJsonFile(path), path.string());
}

Scene sceneFromDescription(const nlohmann::json& description, const std::string& subject) {
  return SceneDescriptionReader(description, subject).read();
}

std::filesystem::path assetDirectory() {
  if (const char* overridden = std::getenv("TRIWALK_ASSETS")) return overridden;
  return TRIWALK_SOURCE_ASSET_DIR;
}

std::filesystem::path builtinScenePath() { return assetDirectory() / "builtin_scene.json"; }

}  // namespace triwalk

#include "scene/assimp_scene.h"

#include "core/image/color.h"
#include "core/io/png_io.h"
#include "core/support/errors.h"
#include "scene/quake3_archive.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <map>
#include <memory>
#include <unistd.h>

namespace triwalk {

namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// Rotation taking the file's up axis to +z, keeping a right-handed frame.
glm::mat3 upAxisToZ(const std::string& axis) {
  if (axis == "y") return glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0));  // (x, y, z) -> (x, -z, y)
  if (axis == "x") return glm::mat3(glm::vec3(0, 0, 1), glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0));  // (x, y, z) -> (-z, y, x)
  return glm::mat3(1.0f);
}

// Quake 3 surfaces that are never seen: the sky box (the sky shows through
// at infinity instead) and the editor's tool textures.
bool invisibleQuake3Surface(const std::string& texture) {
  const std::string name = lowercase(texture);
  return name.find("skies/") != std::string::npos || name.find("/sky") != std::string::npos ||
         name.find("common/") != std::string::npos;
}

class SceneConverter {
public:
  SceneConverter(const std::filesystem::path& file, const aiScene& scene, bool quake3,
                 const std::vector<const ZipArchive*>& archives, SceneImportReport& report)
      : file_(file), scene_(scene), quake3_(quake3), archives_(archives), report_(report) {}

  // The texture a material path names, as an index into result.textures, or -1.
  int texture(const aiString& path, Scene& result) {
    const std::string name = path.C_Str();
    const auto known = loaded_.find(name);
    if (known != loaded_.end()) return known->second;
    int index = -1;
    try {
      std::optional<Rgba8Image> image;
      if (!name.empty() && name[0] == '*') {
        const int embedded = std::atoi(name.c_str() + 1);
        if (embedded >= 0 && unsigned(embedded) < scene_.mNumTextures) image = decodeEmbedded(*scene_.mTextures[embedded]);
      } else if (quake3_) {
        if (const auto bytes = findQuake3Texture(archives_, name)) image = decodeImage(*bytes, name);
      } else {
        const std::filesystem::path candidate = file_.parent_path() / name;
        if (std::filesystem::exists(candidate)) {
          const std::string text = readBinary(candidate);
          image = decodeImage(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()), candidate.string());
        }
      }
      if (image) {
        index = int(result.textures.size());
        result.textures.push_back({name, image->width, image->height, std::move(image->rgba)});
        ++report_.texturesLoaded;
      }
    } catch (const InputError&) {
      index = -1;  // undecodable: reported as missing below
    }
    if (index < 0) report_.missingTextures.push_back(name);
    loaded_[name] = index;
    return index;
  }

private:
  static std::string readBinary(const std::filesystem::path& path) {
    std::string text;
    if (FILE* f = std::fopen(path.string().c_str(), "rb")) {
      char buffer[65536];
      size_t n;
      while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
      std::fclose(f);
    }
    return text;
  }

  Rgba8Image decodeEmbedded(const aiTexture& texture) {
    if (texture.mHeight == 0) {  // a compressed file (jpg, png, tga) in memory
      return decodeImage(std::span(reinterpret_cast<const uint8_t*>(texture.pcData), texture.mWidth), "embedded texture");
    }
    Rgba8Image image{int(texture.mWidth), int(texture.mHeight), std::vector<uint8_t>(size_t(texture.mWidth) * texture.mHeight * 4)};
    for (size_t i = 0; i < size_t(texture.mWidth) * texture.mHeight; ++i) {
      const aiTexel& t = texture.pcData[i];
      image.rgba[4 * i] = t.r, image.rgba[4 * i + 1] = t.g, image.rgba[4 * i + 2] = t.b, image.rgba[4 * i + 3] = t.a;
    }
    return image;
  }

  std::filesystem::path file_;
  const aiScene& scene_;
  bool quake3_;
  std::vector<const ZipArchive*> archives_;
  SceneImportReport& report_;
  std::map<std::string, int> loaded_;
};

// The meshes of IFC door elements: the IFC importer names their nodes
// "IfcDoor_<name>_<id>".
void collectDoorMeshes(const aiNode& node, bool inDoor, std::vector<bool>& doorMesh) {
  inDoor |= std::string(node.mName.C_Str()).rfind("IfcDoor_", 0) == 0;
  if (inDoor) {
    for (unsigned i = 0; i < node.mNumMeshes; ++i) doorMesh[node.mMeshes[i]] = true;
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) collectDoorMeshes(*node.mChildren[i], inDoor, doorMesh);
}

// Materials that only door meshes use (a material shared with a wall stays solid).
std::vector<bool> doorOnlyMaterials(const aiScene& scene, int& doorMeshes) {
  std::vector<bool> doorMesh(scene.mNumMeshes, false);
  collectDoorMeshes(*scene.mRootNode, false, doorMesh);
  doorMeshes = int(std::count(doorMesh.begin(), doorMesh.end(), true));
  std::vector<bool> door(scene.mNumMaterials, false), solid(scene.mNumMaterials, false);
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) (doorMesh[i] ? door : solid)[scene.mMeshes[i]->mMaterialIndex] = true;
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) door[m] = door[m] && !solid[m];
  return door;
}

}  // namespace

Scene importScene(const std::filesystem::path& file, const SceneImportOptions& options, SceneImportReport& report) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), "scene file does not exist");
  const std::string extension = lowercase(file.extension().string());
  const bool quake3 = extension == ".pk3" || extension == ".bsp";

  // Quake 3: the chosen map alone in a temporary archive; textures from it
  // and from the game's other archives beside it.
  std::vector<std::unique_ptr<ZipArchive>> archives;
  std::filesystem::path readPath = file;
  std::filesystem::path temporary;
  if (extension == ".pk3") {
    archives.push_back(std::make_unique<ZipArchive>(file));
    const std::vector<std::string> maps = quake3Maps(*archives.front());
    if (maps.empty()) throw InputError(file.string(), "the archive holds no maps/*.bsp");
    report.map = options.map.empty() ? maps.front() : options.map;
    temporary = std::filesystem::temp_directory_path() / ("triwalk-" + std::to_string(::getpid()) + "-" + report.map + ".pk3");
    writeSingleMapArchive(*archives.front(), report.map, temporary);
    readPath = temporary;
    report.spawnPoints = quake3SpawnPoints(archives.front()->read("maps/" + report.map + ".bsp"), file.string());
    for (const auto& entry : std::filesystem::directory_iterator(file.parent_path())) {
      if (entry.path() != file && lowercase(entry.path().extension().string()) == ".pk3") {
        try {
          archives.push_back(std::make_unique<ZipArchive>(entry.path()));
        } catch (const InputError&) {
          // An unreadable neighbour only means fewer textures.
        }
      }
    }
  }

  Assimp::Importer importer;
  const aiScene* imported = importer.ReadFile(
      readPath.string(), aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices * (quake3 ? 0 : 1));
  if (!temporary.empty()) std::filesystem::remove(temporary);
  if (!imported || !imported->mRootNode || imported->mNumMeshes == 0) {
    const std::string reason = importer.GetErrorString();
    throw InputError(file.string(), "cannot import scene: " + (reason.empty() ? std::string("no meshes") : reason));
  }
  // Door elements are known by their nodes, which flattening the node
  // graph removes; their materials (the IFC importer gives every mesh its
  // own) survive it.
  const std::vector<bool> doorMaterial = doorOnlyMaterials(*imported, report.doorMeshes);
  imported = importer.ApplyPostProcessing(aiProcess_PreTransformVertices);
  if (!imported || imported->mNumMeshes == 0) throw InputError(file.string(), "cannot import scene: " + std::string(importer.GetErrorString()));

  const float scale = options.unitScale > 0.0f ? options.unitScale : (quake3 ? 0.0254f : 1.0f);
  const std::string up = options.upAxis == "auto" ? (quake3 ? "z" : "y") : options.upAxis;
  const glm::mat3 rotation = upAxisToZ(up);
  for (glm::vec3& spawn : report.spawnPoints) spawn = rotation * spawn * scale;

  std::vector<const ZipArchive*> archivePointers;
  for (const auto& archive : archives) archivePointers.push_back(archive.get());
  SceneConverter converter(file, *imported, quake3, archivePointers, report);
  Scene scene;
  scene.name = file.stem().string() + (report.map.empty() ? "" : ":" + report.map);
  std::vector<int> materialOf(imported->mNumMaterials, -1);
  std::vector<bool> invisible(imported->mNumMaterials, false);
  for (unsigned m = 0; m < imported->mNumMaterials; ++m) {
    const aiMaterial& source = *imported->mMaterials[m];
    SceneMaterial material;
    aiString name;
    source.Get(AI_MATKEY_NAME, name);
    material.name = name.C_Str();
    aiColor3D diffuse(1.0f, 1.0f, 1.0f);
    if (source.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
      material.baseColor = {srgbToLinear(diffuse.r), srgbToLinear(diffuse.g), srgbToLinear(diffuse.b)};
    }
    aiString path;
    if (source.GetTexture(aiTextureType_DIFFUSE, 0, &path) == AI_SUCCESS) {
      if (quake3 && invisibleQuake3Surface(path.C_Str())) invisible[m] = true;
      material.diffuseTexture = converter.texture(path, scene);
      if (material.diffuseTexture < 0) material.baseColor = glm::vec3(0.45f);  // neutral stand-in
      material.alphaTest = material.diffuseTexture >= 0;
    }
    aiString lightmap;
    if (source.GetTexture(aiTextureType_LIGHTMAP, 1, &lightmap) == AI_SUCCESS ||
        source.GetTexture(aiTextureType_LIGHTMAP, 0, &lightmap) == AI_SUCCESS) {
      material.lightmapTexture = converter.texture(lightmap, scene);
      // Quake 3 doubles lightmaps (overbright) and multiplies in display
      // space; in linear space that is about 2^2.2.
      material.lightmapScale = 4.6f;
    }
    float shininess = 0.0f, strength = 0.0f;
    if (source.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 1.0f &&
        source.Get(AI_MATKEY_SHININESS_STRENGTH, strength) == AI_SUCCESS && strength > 0.0f) {
      material.specular = std::min(strength, 1.0f) * 0.5f;
      material.shininess = shininess;
    }
    material.passable = doorMaterial[m];
    materialOf[m] = int(scene.materials.size());
    scene.materials.push_back(material);
  }

  for (unsigned i = 0; i < imported->mNumMeshes; ++i) {
    const aiMesh& source = *imported->mMeshes[i];
    if (invisible[source.mMaterialIndex] || !(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    SceneMesh mesh;
    mesh.material = materialOf[source.mMaterialIndex];
    const bool hasColors = source.HasVertexColors(0);
    if (hasColors) scene.materials[size_t(mesh.material)].useVertexColor = true;
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
      SceneVertex vertex;
      const aiVector3D p = source.mVertices[v];
      vertex.position = rotation * glm::vec3(p.x, p.y, p.z) * scale;
      if (source.HasNormals()) vertex.normal = rotation * glm::vec3(source.mNormals[v].x, source.mNormals[v].y, source.mNormals[v].z);
      if (source.HasTextureCoords(0)) vertex.uv = {source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y};
      if (source.HasTextureCoords(1)) vertex.lightmapUv = {source.mTextureCoords[1][v].x, source.mTextureCoords[1][v].y};
      if (hasColors) {
        const aiColor4D c = source.mColors[0][v];
        vertex.color = {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a};
      }
      mesh.vertices.push_back(vertex);
    }
    if (quake3) {
      // Debian's Assimp 5.2 leaves Quake 3 face indices uninitialized; its
      // vertices come as consecutive triangles.
      for (unsigned v = 0; v + 2 < source.mNumVertices; v += 3) mesh.indices.insert(mesh.indices.end(), {v, v + 1, v + 2});
    } else {
      for (unsigned f = 0; f < source.mNumFaces; ++f) {
        if (source.mFaces[f].mNumIndices != 3) continue;
        mesh.indices.insert(mesh.indices.end(), source.mFaces[f].mIndices, source.mFaces[f].mIndices + 3);
      }
    }
    if (!mesh.indices.empty()) scene.meshes.push_back(std::move(mesh));
  }
  if (scene.meshes.empty()) throw InputError(file.string(), "the scene has no visible triangles");

  // Lighting for scenes without lightmaps: ambient light and a far light
  // above, fixed in the world, so that shading never depends on the view.
  glm::vec3 lower, upper;
  scene.bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  const bool lightmapped = std::any_of(scene.materials.begin(), scene.materials.end(),
                                       [](const SceneMaterial& m) { return m.lightmapTexture >= 0; });
  scene.ambient = lightmapped ? glm::vec3(0.0f) : glm::vec3(0.45f);
  if (!lightmapped) scene.lights.push_back({centre + glm::vec3(-300.0f, -500.0f, 800.0f), glm::vec3(0.7f), 1.0e4f});
  scene.spawnPoints = report.spawnPoints;
  scene.walkableArea.min = glm::vec2(centre) - 0.5f;
  scene.walkableArea.max = glm::vec2(centre) + 0.5f;
  scene.walkableArea.floorHeight = lower.z;
  return scene;
}

}  // namespace triwalk

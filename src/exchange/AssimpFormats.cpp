// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Scene <-> OBJ/MTL and STL through Assimp 5.2 (Debian's libassimp-dev).
// Writing builds an aiScene by hand, flattened: each node that draws a mesh
// gives that mesh again with its world matrix applied (OBJ and STL have no
// hierarchy, and Assimp's STL exporter ignores nodes). Reading walks the
// aiScene Assimp gives (triangulated) into a Scene.

#include "exchange/AssimpFormats.h"

#include "core/Error.h"
#include "exchange/Png.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <fstream>
#include <iterator>
#include <memory>

namespace q3::exchange {

namespace {

glm::dmat4 matrixOf(const std::array<double, 16>& m)
{
    // Row-vector matrix stored row by row = glm's column-major column-vector
    // matrix (base/Matrix.h).
    glm::dmat4 out(1.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            out[i][j] = m[4 * i + j];
    return out;
}

struct Instance {
    int mesh;
    glm::dmat4 world;
};

void instances(const Scene& scene, int node, const glm::dmat4& parent, std::vector<Instance>& out, int depth)
{
    if (depth > 1024)
        fail(kQ3ErrorInvalidData, "nodes nest too deep");
    const Node& n = scene.nodes[node];
    const glm::dmat4 world = parent * (n.hasMatrix ? matrixOf(n.matrix) : glm::dmat4(1.0));
    if (n.mesh >= 0)
        out.push_back(Instance{n.mesh, world});
    for (int child : n.children)
        instances(scene, child, world, out, depth + 1);
}

// The flattened scene Assimp exports. trianglesOnly: STL.
std::unique_ptr<aiScene> aiSceneOf(const Scene& scene, bool trianglesOnly, const std::string& stem)
{
    std::vector<Instance> all;
    for (int root : scene.roots)
        instances(scene, root, glm::dmat4(1.0), all, 0);
    auto out = std::make_unique<aiScene>();
    out->mRootNode = new aiNode("root");

    out->mNumMaterials = static_cast<unsigned>(std::max<std::size_t>(scene.materials.size(), 1));
    out->mMaterials = new aiMaterial*[out->mNumMaterials];
    for (unsigned i = 0; i < out->mNumMaterials; ++i) {
        auto* material = new aiMaterial();
        out->mMaterials[i] = material;
        const Material m = i < scene.materials.size() ? scene.materials[i] : Material{};
        const aiString name("material" + std::to_string(i));
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor3D diffuse(m.diffuse.r, m.diffuse.g, m.diffuse.b);
        const aiColor3D specular(m.specular.r, m.specular.g, m.specular.b);
        material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
        material->AddProperty(&specular, 1, AI_MATKEY_COLOR_SPECULAR);
        material->AddProperty(&m.specularControl, 1, AI_MATKEY_SHININESS);
        material->AddProperty(&m.alpha, 1, AI_MATKEY_OPACITY);
        const int shading = m.illumination == kQ3IlluminationTypePhong     ? aiShadingMode_Phong
                            : m.illumination == kQ3IlluminationTypeLambert ? aiShadingMode_Gouraud
                                                                           : aiShadingMode_NoShading;
        material->AddProperty(&shading, 1, AI_MATKEY_SHADING_MODEL);
        if (m.image >= 0) {
            const aiString file(stem + "_" + std::to_string(m.image) + ".png");
            material->AddProperty(&file, AI_MATKEY_TEXTURE_DIFFUSE(0));
        }
    }

    std::vector<aiMesh*> meshes;
    for (const Instance& instance : all) {
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(instance.world)));
        for (const Primitive& p : scene.meshes[instance.mesh].primitives) {
            if (trianglesOnly && p.mode != Primitive::Mode::kTriangles)
                continue;
            if (p.mode == Primitive::Mode::kLineStrip && p.indices.size() < 2)
                continue;
            auto* mesh = new aiMesh();
            meshes.push_back(mesh);
            mesh->mMaterialIndex = p.material >= 0 ? unsigned(p.material) : 0;
            const std::size_t count = p.positions.size() / 3;
            mesh->mNumVertices = unsigned(count);
            mesh->mVertices = new aiVector3D[count];
            for (std::size_t i = 0; i < count; ++i) {
                const glm::dvec4 v = instance.world * glm::dvec4(p.positions[3 * i], p.positions[3 * i + 1],
                                                                 p.positions[3 * i + 2], 1.0);
                mesh->mVertices[i] = aiVector3D(float(v.x / v.w), float(v.y / v.w), float(v.z / v.w));
            }
            if (p.normals.size() == 3 * count) {
                mesh->mNormals = new aiVector3D[count];
                for (std::size_t i = 0; i < count; ++i) {
                    glm::dvec3 n = normalMatrix * glm::dvec3(p.normals[3 * i], p.normals[3 * i + 1], p.normals[3 * i + 2]);
                    const double length = glm::length(n);
                    n = length > 0.0 ? n / length : glm::dvec3(0, 0, 1);
                    mesh->mNormals[i] = aiVector3D(float(n.x), float(n.y), float(n.z));
                }
            }
            if (!trianglesOnly && p.uvs.size() == 2 * count) {
                mesh->mTextureCoords[0] = new aiVector3D[count];
                mesh->mNumUVComponents[0] = 2;
                for (std::size_t i = 0; i < count; ++i)
                    mesh->mTextureCoords[0][i] = aiVector3D(p.uvs[2 * i], p.uvs[2 * i + 1], 0.0f);
            }
            if (!trianglesOnly && p.colors.size() == 4 * count) {
                mesh->mColors[0] = new aiColor4D[count];
                for (std::size_t i = 0; i < count; ++i)
                    mesh->mColors[0][i] =
                        aiColor4D(p.colors[4 * i], p.colors[4 * i + 1], p.colors[4 * i + 2], p.colors[4 * i + 3]);
            }
            std::vector<std::vector<unsigned>> faces;
            switch (p.mode) {
            case Primitive::Mode::kTriangles:
                mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
                for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3)
                    faces.push_back({p.indices[t], p.indices[t + 1], p.indices[t + 2]});
                break;
            case Primitive::Mode::kLineStrip:
                mesh->mPrimitiveTypes = aiPrimitiveType_LINE;
                for (std::size_t k = 0; k + 1 < p.indices.size(); ++k)
                    faces.push_back({p.indices[k], p.indices[k + 1]});
                break;
            case Primitive::Mode::kLines:
                mesh->mPrimitiveTypes = aiPrimitiveType_LINE;
                for (std::size_t k = 0; k + 1 < p.indices.size(); k += 2)
                    faces.push_back({p.indices[k], p.indices[k + 1]});
                break;
            case Primitive::Mode::kPoints:
                mesh->mPrimitiveTypes = aiPrimitiveType_POINT;
                for (std::uint32_t i : p.indices)
                    faces.push_back({i});
                break;
            }
            mesh->mNumFaces = unsigned(faces.size());
            mesh->mFaces = new aiFace[faces.size()];
            for (std::size_t f = 0; f < faces.size(); ++f) {
                mesh->mFaces[f].mNumIndices = unsigned(faces[f].size());
                mesh->mFaces[f].mIndices = new unsigned[faces[f].size()];
                std::copy(faces[f].begin(), faces[f].end(), mesh->mFaces[f].mIndices);
            }
        }
    }
    out->mNumMeshes = unsigned(meshes.size());
    out->mMeshes = new aiMesh*[std::max<std::size_t>(meshes.size(), 1)];
    std::copy(meshes.begin(), meshes.end(), out->mMeshes);
    out->mRootNode->mNumMeshes = out->mNumMeshes;
    out->mRootNode->mMeshes = new unsigned[std::max<std::size_t>(meshes.size(), 1)];
    for (unsigned i = 0; i < out->mNumMeshes; ++i)
        out->mRootNode->mMeshes[i] = i;
    return out;
}

void exportWith(const aiScene& scene, const char* format, const std::string& path)
{
    Assimp::Exporter exporter;
    if (exporter.Export(&scene, format, path) != aiReturn_SUCCESS)
        fail(kQ3ErrorFileNotOpen, "cannot write " + path + ": " + exporter.GetErrorString());
}

std::vector<unsigned char> fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        fail(kQ3ErrorFileNotOpen, "cannot open " + path);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string directoryOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

// Assimp reads an OBJ whose material library is missing with a warning and
// grey materials; Q3 makes it an error, so that nothing is silently lost.
void requireMaterialFiles(const std::string& path)
{
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("mtllib", 0) != 0)
            continue;
        std::string name = line.substr(6);
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front())))
            name.erase(name.begin());
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
            name.pop_back();
        const std::string file = directoryOf(path) + "/" + name;
        if (!std::ifstream(file).good())
            fail(kQ3ErrorInvalidData, path + " names the material file " + name + ", which cannot be opened");
    }
}

} // namespace

void writeObj(const Scene& scene, const std::string& directory, const std::string& stem)
{
    const std::unique_ptr<aiScene> flat = aiSceneOf(scene, false, stem);
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const std::vector<unsigned char> png = encodePng(scene.images[i]);
        const std::string file = directory + "/" + stem + "_" + std::to_string(i) + ".png";
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
        if (!out)
            fail(kQ3ErrorFileNotOpen, "cannot write " + file);
    }
    exportWith(*flat, "obj", directory + "/" + stem + ".obj");
}

void writeStl(const Scene& scene, const std::string& path)
{
    exportWith(*aiSceneOf(scene, true, ""), "stlb", path);
}

Scene readWithAssimp(const std::string& path)
{
    if (!std::ifstream(path).good())
        fail(kQ3ErrorFileNotOpen, "cannot open " + path);
    const bool obj = path.size() >= 4 && (path.compare(path.size() - 4, 4, ".obj") == 0 ||
                                          path.compare(path.size() - 4, 4, ".OBJ") == 0);
    if (obj)
        requireMaterialFiles(path);
    Assimp::Importer importer;
    const aiScene* in = importer.ReadFile(path, aiProcess_Triangulate);
    if (in == nullptr || (in->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || in->mRootNode == nullptr)
        fail(kQ3ErrorInvalidData, path + " cannot be read: " + importer.GetErrorString());

    Scene scene;
    std::map<std::string, int> images;
    for (unsigned i = 0; i < in->mNumMaterials; ++i) {
        const aiMaterial* m = in->mMaterials[i];
        Material out;
        out.illumination = kQ3IlluminationTypePhong;
        aiColor3D color;
        if (m->Get(AI_MATKEY_COLOR_DIFFUSE, color) == aiReturn_SUCCESS)
            out.diffuse = TQ3ColorRGB{color.r, color.g, color.b};
        if (m->Get(AI_MATKEY_COLOR_SPECULAR, color) == aiReturn_SUCCESS)
            out.specular = TQ3ColorRGB{color.r, color.g, color.b};
        float value = 0.0f;
        if (m->Get(AI_MATKEY_SHININESS, value) == aiReturn_SUCCESS && value >= 0.0f)
            out.specularControl = value;
        if (m->Get(AI_MATKEY_OPACITY, value) == aiReturn_SUCCESS && value >= 0.0f && value <= 1.0f)
            out.alpha = value;
        aiString texture;
        if (m->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == aiReturn_SUCCESS && texture.length > 0) {
            const std::string file = directoryOf(path) + "/" + texture.C_Str();
            auto found = images.find(file);
            if (found == images.end()) {
                if (!std::ifstream(file).good())
                    fail(kQ3ErrorInvalidData, path + " names the texture " + texture.C_Str() +
                                                  ", which cannot be opened");
                const std::vector<unsigned char> bytes = fileBytes(file);
                found = images.emplace(file, int(scene.images.size())).first;
                scene.images.push_back(decodePng(bytes.data(), bytes.size(), file));
            }
            out.image = found->second;
        }
        scene.materials.push_back(out);
    }
    for (unsigned i = 0; i < in->mNumMeshes; ++i) {
        const aiMesh* m = in->mMeshes[i];
        Mesh mesh;
        mesh.name = m->mName.C_Str();
        Primitive tri, lines, points;
        tri.mode = Primitive::Mode::kTriangles;
        lines.mode = Primitive::Mode::kLines;
        points.mode = Primitive::Mode::kPoints;
        for (Primitive* p : {&tri, &lines, &points}) {
            p->material = m->mMaterialIndex < scene.materials.size() ? int(m->mMaterialIndex) : -1;
            for (unsigned v = 0; v < m->mNumVertices; ++v) {
                p->positions.insert(p->positions.end(), {m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z});
                if (m->mNormals != nullptr)
                    p->normals.insert(p->normals.end(), {m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z});
                if (m->mTextureCoords[0] != nullptr)
                    p->uvs.insert(p->uvs.end(), {m->mTextureCoords[0][v].x, m->mTextureCoords[0][v].y});
                if (m->mColors[0] != nullptr)
                    p->colors.insert(p->colors.end(), {m->mColors[0][v].r, m->mColors[0][v].g, m->mColors[0][v].b,
                                                       m->mColors[0][v].a});
            }
        }
        for (unsigned f = 0; f < m->mNumFaces; ++f) {
            const aiFace& face = m->mFaces[f];
            Primitive& p = face.mNumIndices == 3 ? tri : face.mNumIndices == 2 ? lines : points;
            if (face.mNumIndices > 3)
                continue;
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= m->mNumVertices)
                    fail(kQ3ErrorInvalidData, path + ": a face refers past its vertices");
                p.indices.push_back(face.mIndices[k]);
            }
        }
        for (Primitive* p : {&tri, &lines, &points})
            if (!p->indices.empty())
                mesh.primitives.push_back(std::move(*p));
        scene.meshes.push_back(std::move(mesh));
    }
    // The node tree; Assimp's matrices are column-vector, row by row.
    std::function<int(const aiNode*, int)> add = [&](const aiNode* node, int depth) -> int {
        if (depth > 1024)
            fail(kQ3ErrorInvalidData, path + ": nodes nest too deep");
        const int index = int(scene.nodes.size());
        scene.nodes.emplace_back();
        Node out;
        out.name = node->mName.C_Str();
        const aiMatrix4x4& t = node->mTransformation;
        const float rows[4][4] = {{t.a1, t.a2, t.a3, t.a4}, {t.b1, t.b2, t.b3, t.b4}, {t.c1, t.c2, t.c3, t.c4},
                                  {t.d1, t.d2, t.d3, t.d4}};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                out.matrix[4 * i + j] = rows[j][i];
        out.hasMatrix = out.matrix != Node{}.matrix;
        for (unsigned k = 0; k < node->mNumMeshes; ++k) {
            if (node->mMeshes[k] >= in->mNumMeshes)
                fail(kQ3ErrorInvalidData, path + ": a node refers to no mesh");
            // A node may draw several meshes: one child node each.
            const int child = int(scene.nodes.size());
            scene.nodes.emplace_back();
            scene.nodes[child].mesh = int(node->mMeshes[k]);
            out.children.push_back(child);
        }
        for (unsigned k = 0; k < node->mNumChildren; ++k)
            out.children.push_back(add(node->mChildren[k], depth + 1));
        scene.nodes[index] = out;
        return index;
    };
    scene.roots.push_back(add(in->mRootNode, 0));
    return scene;
}

} // namespace q3::exchange

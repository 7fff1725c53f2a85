// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Scene <-> glTF 2.0 (the Khronos specification, 2.0.1) through tinygltf's
// Model. tinygltf parses and serializes the JSON and the GLB container; Q3
// packs and unpacks the buffer itself (accessors, bufferViews) and its
// images as PNG (exchange/Png.h), so that a texture's pixels reach the file
// exactly. docs/exchange.md lists every mapping.

#include "exchange/Gltf.h"

#include "core/Error.h"
#include "core/Limits.h"
#include "exchange/Png.h"

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace q3::exchange {

namespace {

using tinygltf::Value;

constexpr const char* kUnlit = "KHR_materials_unlit";
constexpr const char* kTextureTransform = "KHR_texture_transform";

class Packer {
public:
    explicit Packer(tinygltf::Model& model) : m_model(model) { m_model.buffers.emplace_back(); }

    int view(const void* data, std::size_t size, int target)
    {
        std::vector<unsigned char>& bytes = m_model.buffers[0].data;
        while (bytes.size() % 4 != 0)
            bytes.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = bytes.size();
        view.byteLength = size;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), p, p + size);
        m_model.bufferViews.push_back(view);
        return int(m_model.bufferViews.size() - 1);
    }

    int floats(const std::vector<float>& values, int components, bool bounds)
    {
        tinygltf::Accessor accessor;
        accessor.bufferView = view(values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size() / components;
        accessor.type = components == 2 ? TINYGLTF_TYPE_VEC2 : components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
        if (bounds) {
            accessor.minValues.assign(components, std::numeric_limits<double>::infinity());
            accessor.maxValues.assign(components, -std::numeric_limits<double>::infinity());
            for (std::size_t i = 0; i < values.size(); ++i) {
                double& low = accessor.minValues[i % components];
                double& high = accessor.maxValues[i % components];
                low = std::min(low, double(values[i]));
                high = std::max(high, double(values[i]));
            }
        }
        m_model.accessors.push_back(accessor);
        return int(m_model.accessors.size() - 1);
    }

    int indices(const std::vector<std::uint32_t>& values)
    {
        tinygltf::Accessor accessor;
        accessor.bufferView =
            view(values.data(), values.size() * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        m_model.accessors.push_back(accessor);
        return int(m_model.accessors.size() - 1);
    }

private:
    tinygltf::Model& m_model;
};

Value numbers(std::initializer_list<double> list)
{
    Value::Array array;
    for (double d : list)
        array.emplace_back(d);
    return Value(std::move(array));
}

int wrapOf(TQ3ShaderUVBoundary boundary)
{
    return boundary == kQ3ShaderUVBoundaryClamp ? TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE : TINYGLTF_TEXTURE_WRAP_REPEAT;
}

TQ3ShaderUVBoundary boundaryOf(int wrap)
{
    // Mirrored repeat has no QuickDraw 3D counterpart; it repeats.
    return wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE ? kQ3ShaderUVBoundaryClamp : kQ3ShaderUVBoundaryWrap;
}

int modeOf(Primitive::Mode mode)
{
    switch (mode) {
    case Primitive::Mode::kTriangles:
        return TINYGLTF_MODE_TRIANGLES;
    case Primitive::Mode::kLineStrip:
        return TINYGLTF_MODE_LINE_STRIP;
    case Primitive::Mode::kLines:
        return TINYGLTF_MODE_LINE;
    default:
        return TINYGLTF_MODE_POINTS;
    }
}

void buildMaterials(const Scene& scene, tinygltf::Model& model)
{
    std::vector<std::array<int, 3>> textures; // image, wrapS, wrapT
    bool unlit = false;
    for (const Material& m : scene.materials) {
        tinygltf::Material out;
        auto& pbr = out.pbrMetallicRoughness;
        const bool textured = m.image >= 0;
        // A texture or vertex colours take the diffuse colour's place, as
        // QuickDraw 3D draws them; the colour itself is kept in extras.
        if (textured || m.vertexColors)
            pbr.baseColorFactor = {1.0, 1.0, 1.0, m.vertexColors ? 1.0 : double(m.alpha)};
        else
            pbr.baseColorFactor = {m.diffuse.r, m.diffuse.g, m.diffuse.b, m.alpha};
        pbr.metallicFactor = 0.0;
        pbr.roughnessFactor = m.illumination == kQ3IlluminationTypePhong ? roughnessFromSpecularControl(m.specularControl)
                                                                          : 1.0;
        if (m.illumination != kQ3IlluminationTypePhong && m.illumination != kQ3IlluminationTypeLambert) {
            out.extensions[kUnlit] = Value(Value::Object());
            unlit = true;
        }
        out.doubleSided = true;
        const bool translucent = m.alpha < 1.0f || (textured && scene.images[m.image].hasAlpha);
        out.alphaMode = translucent ? "BLEND" : "OPAQUE";
        if (textured) {
            const std::array<int, 3> key{m.image, wrapOf(m.uBoundary), wrapOf(m.vBoundary)};
            auto found = std::find(textures.begin(), textures.end(), key);
            if (found == textures.end()) {
                textures.push_back(key);
                found = textures.end() - 1;
            }
            pbr.baseColorTexture.index = int(found - textures.begin());
        }
        Value::Object q3;
        q3["diffuseColor"] = numbers({m.diffuse.r, m.diffuse.g, m.diffuse.b});
        q3["specularColor"] = numbers({m.specular.r, m.specular.g, m.specular.b});
        q3["specularControl"] = Value(double(m.specularControl));
        q3["illumination"] = Value(m.illumination == kQ3IlluminationTypePhong     ? std::string("phong")
                                   : m.illumination == kQ3IlluminationTypeLambert ? std::string("lambert")
                                                                                   : std::string("null"));
        Value::Object extras;
        extras["q3"] = Value(std::move(q3));
        out.extras = Value(std::move(extras));
        model.materials.push_back(out);
    }
    if (unlit)
        model.extensionsUsed.push_back(kUnlit);
    for (const auto& [image, wrapS, wrapT] : textures) {
        tinygltf::Sampler s;
        s.wrapS = wrapS;
        s.wrapT = wrapT;
        s.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        s.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        model.samplers.push_back(s);
        tinygltf::Texture t;
        t.source = image;
        t.sampler = int(model.samplers.size() - 1);
        model.textures.push_back(t);
    }
}

} // namespace

void writeGltf(const Scene& scene, const std::string& path, bool binary)
{
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Q3";
    Packer packer(model);

    for (const Image& image : scene.images) {
        const std::vector<unsigned char> png = encodePng(image);
        tinygltf::Image out;
        out.bufferView = packer.view(png.data(), png.size(), 0);
        out.mimeType = "image/png";
        model.images.push_back(out);
    }
    buildMaterials(scene, model);

    for (const Mesh& mesh : scene.meshes) {
        tinygltf::Mesh out;
        out.name = mesh.name;
        for (const Primitive& p : mesh.primitives) {
            tinygltf::Primitive prim;
            prim.mode = modeOf(p.mode);
            prim.material = p.material;
            prim.attributes["POSITION"] = packer.floats(p.positions, 3, true);
            if (!p.normals.empty())
                prim.attributes["NORMAL"] = packer.floats(p.normals, 3, false);
            if (!p.uvs.empty()) {
                // glTF's t runs down from the image's top row, v up from its bottom.
                std::vector<float> st(p.uvs);
                for (std::size_t i = 1; i < st.size(); i += 2)
                    st[i] = 1.0f - st[i];
                prim.attributes["TEXCOORD_0"] = packer.floats(st, 2, false);
            }
            if (!p.colors.empty()) {
                std::vector<float> colors(p.colors);
                for (float& c : colors)
                    c = std::clamp(c, 0.0f, 1.0f);
                prim.attributes["COLOR_0"] = packer.floats(colors, 4, false);
            }
            prim.indices = packer.indices(p.indices);
            out.primitives.push_back(prim);
        }
        model.meshes.push_back(out);
    }

    for (const Camera& c : scene.cameras) {
        tinygltf::Camera out;
        if (c.perspective) {
            out.type = "perspective";
            out.perspective.yfov = c.yfov;
            out.perspective.aspectRatio = c.aspect;
            out.perspective.znear = c.znear;
            out.perspective.zfar = c.zfar;
        } else {
            out.type = "orthographic";
            out.orthographic.xmag = c.xmag;
            out.orthographic.ymag = c.ymag;
            out.orthographic.znear = c.znear;
            out.orthographic.zfar = c.zfar;
        }
        model.cameras.push_back(out);
    }
    for (const Light& l : scene.lights) {
        tinygltf::Light out;
        out.type = l.kind == Light::Kind::kDirectional ? "directional" : l.kind == Light::Kind::kPoint ? "point" : "spot";
        out.color = {l.color.r, l.color.g, l.color.b};
        out.intensity = l.intensity;
        out.spot.innerConeAngle = l.innerCone;
        out.spot.outerConeAngle = l.outerCone;
        model.lights.push_back(out);
    }

    for (const Node& n : scene.nodes) {
        tinygltf::Node out;
        out.name = n.name;
        out.mesh = n.mesh;
        out.camera = n.camera;
        out.children = n.children;
        // A row-vector matrix stored row by row is the column-vector matrix
        // stored column by column: glTF's layout (base/Matrix.h).
        if (n.hasMatrix)
            out.matrix.assign(n.matrix.begin(), n.matrix.end());
        if (n.light >= 0) {
            Value::Object ref;
            ref["light"] = Value(n.light);
            out.extensions["KHR_lights_punctual"] = Value(std::move(ref));
        }
        model.nodes.push_back(out);
    }
    tinygltf::Scene s;
    s.nodes = scene.roots;
    model.scenes.push_back(s);
    model.defaultScene = 0;
    if (model.buffers[0].data.empty())
        model.buffers.clear();

    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, !binary, binary))
        fail(kQ3ErrorFileNotOpen, "cannot write " + path);
}

namespace {

bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
               const unsigned char* bytes, int size, void*)
{
    try {
        const Image decoded = decodePng(bytes, std::size_t(size), "image " + std::to_string(index));
        image->width = int(decoded.width);
        image->height = int(decoded.height);
        image->component = 4;
        image->bits = 8;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        image->image = decoded.rgba;
        return true;
    } catch (const Error& e) {
        if (err != nullptr)
            *err += e.what() + std::string(" (Q3 reads PNG textures only)\n");
        return false;
    }
}

// An accessor's elements as floats (normalized integers mapped to 0..1),
// `components` per element.
// The bufferView and buffer an accessor reads, checked to exist.
std::pair<const tinygltf::BufferView*, const tinygltf::Buffer*> viewOf(const tinygltf::Model& model,
                                                                       const tinygltf::Accessor& a, const char* what)
{
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= model.bufferViews.size())
        fail(kQ3ErrorInvalidData, std::string(what) + ": no such bufferView");
    const tinygltf::BufferView& v = model.bufferViews[a.bufferView];
    if (v.buffer < 0 || std::size_t(v.buffer) >= model.buffers.size())
        fail(kQ3ErrorInvalidData, std::string(what) + ": no such buffer");
    return {&v, &model.buffers[v.buffer]};
}

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components, const char* what)
{
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        fail(kQ3ErrorInvalidData, std::string(what) + ": no such accessor");
    const tinygltf::Accessor& a = model.accessors[index];
    const int have = tinygltf::GetNumComponentsInType(a.type);
    if (have != components && !(components == 4 && have == 3))
        fail(kQ3ErrorInvalidData, std::string(what) + ": an accessor of the wrong type");
    // Q3 reads no sparse accessors: one without a bufferView is all zeros,
    // as the specification says, and is refused past the limit on arrays.
    if (a.count > limits::kMaxArrayCount)
        fail(kQ3ErrorInvalidData, std::string(what) + ": more elements than kQ3GeometryMaxArrayCount");
    if (a.bufferView < 0)
        return std::vector<float>(a.count * components, 0.0f);
    const auto [view, buffer] = viewOf(model, a, what);
    const tinygltf::BufferView& v = *view;
    const tinygltf::Buffer& b = *buffer;
    if (a.count > b.data.size())
        fail(kQ3ErrorInvalidData, std::string(what) + ": an accessor reaches past its buffer");
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
    const std::size_t stride = v.byteStride != 0 ? v.byteStride : std::size_t(size) * have;
    const std::size_t start = v.byteOffset + a.byteOffset;
    if (a.count != 0 && (size <= 0 || start + stride * (a.count - 1) + std::size_t(size) * have > b.data.size() ||
                         a.byteOffset + stride * (a.count - 1) + std::size_t(size) * have > v.byteLength))
        fail(kQ3ErrorInvalidData, std::string(what) + ": an accessor reaches past its buffer");
    std::vector<float> out(a.count * components, 1.0f);
    for (std::size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < have; ++c) {
            const unsigned char* p = b.data.data() + start + i * stride + std::size_t(c) * size;
            float value = 0.0f;
            switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT:
                std::memcpy(&value, p, 4);
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                value = p[0] / 255.0f;
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t s;
                std::memcpy(&s, p, 2);
                value = s / 65535.0f;
                break;
            }
            default:
                fail(kQ3ErrorUnsupportedFunctionality, std::string(what) + ": a component type Q3 does not read");
            }
            out[i * components + c] = value;
        }
    return out;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index, std::size_t vertexCount)
{
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        fail(kQ3ErrorInvalidData, "indices: no such accessor");
    const tinygltf::Accessor& a = model.accessors[index];
    if (a.type != TINYGLTF_TYPE_SCALAR ||
        (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(kQ3ErrorInvalidData, "indices that are not unsigned integer scalars");
    if (a.bufferView < 0)
        fail(kQ3ErrorInvalidData, "indices without a bufferView");
    if (a.count > limits::kMaxArrayCount)
        fail(kQ3ErrorInvalidData, "indices: more elements than kQ3GeometryMaxArrayCount");
    const auto [view, buffer] = viewOf(model, a, "indices");
    const tinygltf::BufferView& v = *view;
    const tinygltf::Buffer& b = *buffer;
    const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
    const std::size_t stride = v.byteStride != 0 ? v.byteStride : std::size_t(size);
    const std::size_t start = v.byteOffset + a.byteOffset;
    if (a.count != 0 && (size <= 0 || start + stride * (a.count - 1) + size > b.data.size() ||
                         a.byteOffset + stride * (a.count - 1) + size > v.byteLength))
        fail(kQ3ErrorInvalidData, "indices reach past their buffer");
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = b.data.data() + start + i * stride;
        std::uint32_t value = 0;
        if (size == 1)
            value = p[0];
        else if (size == 2) {
            std::uint16_t s;
            std::memcpy(&s, p, 2);
            value = s;
        } else
            std::memcpy(&value, p, 4);
        if (value >= vertexCount)
            fail(kQ3ErrorInvalidData, "an index refers past the vertices");
        out[i] = value;
    }
    return out;
}

std::array<double, 16> matrixOf(const tinygltf::Node& n)
{
    std::array<double, 16> out{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (n.matrix.size() == 16) {
        std::copy(n.matrix.begin(), n.matrix.end(), out.begin());
        return out;
    }
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3)
        m[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
    if (n.rotation.size() == 4)
        m = m * glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (n.scale.size() == 3)
        m = m * glm::dmat4(glm::dvec4(n.scale[0], 0, 0, 0), glm::dvec4(0, n.scale[1], 0, 0),
                           glm::dvec4(0, 0, n.scale[2], 0), glm::dvec4(0, 0, 0, 1));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            out[4 * i + j] = m[i][j];
    return out;
}

std::vector<std::uint32_t> triangulate(int mode, const std::vector<std::uint32_t>& in)
{
    std::vector<std::uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(in.begin(), in.begin() + in.size() / 3 * 3);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 2; i < in.size(); ++i) {
            if (i % 2 == 0)
                out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
            else
                out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
        }
    } else { // fan
        for (std::size_t i = 2; i < in.size(); ++i)
            out.insert(out.end(), {in[0], in[i - 1], in[i]});
    }
    return out;
}

// KHR_texture_transform on a texture: applied to the uvs (in glTF's s, t),
// since Q3 bakes uv transforms into uvs; as the extension's GLSL has it,
// translation * rotation * scale, the rotation counterclockwise.
void applyTextureTransform(const tinygltf::TextureInfo& info, std::vector<float>& st)
{
    const auto found = info.extensions.find(kTextureTransform);
    if (found == info.extensions.end() || !found->second.IsObject())
        return;
    const Value& t = found->second;
    auto pair = [&](const char* key, double x, double y) {
        const Value& v = t.Get(key);
        if (v.IsArray() && v.ArrayLen() == 2 && v.Get(0).IsNumber() && v.Get(1).IsNumber())
            return std::make_pair(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
        return std::make_pair(x, y);
    };
    const auto [ox, oy] = pair("offset", 0.0, 0.0);
    const auto [sx, sy] = pair("scale", 1.0, 1.0);
    const double r = t.Get("rotation").IsNumber() ? t.Get("rotation").GetNumberAsDouble() : 0.0;
    const double c = std::cos(r), s = std::sin(r);
    for (std::size_t i = 0; i + 1 < st.size(); i += 2) {
        const double u = sx * st[i], v = sy * st[i + 1];
        st[i] = float(c * u - s * v + ox);
        st[i + 1] = float(s * u + c * v + oy);
    }
}

Material materialOf(const tinygltf::Model& model, int index, Scene& scene, std::vector<int>& images)
{
    Material m;
    m.illumination = kQ3IlluminationTypePhong;
    if (index < 0)
        return m;
    const tinygltf::Material& in = model.materials.at(index);
    const auto& pbr = in.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4) {
        m.diffuse = TQ3ColorRGB{float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                float(pbr.baseColorFactor[2])};
        m.alpha = float(pbr.baseColorFactor[3]);
    }
    m.specularControl = float(specularControlFromRoughness(pbr.roughnessFactor));
    if (in.extensions.count(kUnlit) != 0)
        m.illumination = kQ3IlluminationTypeNULL;
    const Value& q3 = in.extras.Get("q3");
    if (q3.IsObject()) {
        auto color = [](const Value& v, TQ3ColorRGB& c) {
            if (v.IsArray() && v.ArrayLen() == 3)
                c = TQ3ColorRGB{float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()),
                                float(v.Get(2).GetNumberAsDouble())};
        };
        color(q3.Get("diffuseColor"), m.diffuse);
        color(q3.Get("specularColor"), m.specular);
        if (q3.Get("specularControl").IsNumber())
            m.specularControl = float(q3.Get("specularControl").GetNumberAsDouble());
        const Value& illumination = q3.Get("illumination");
        if (illumination.IsString())
            m.illumination = illumination.Get<std::string>() == "lambert" ? kQ3IlluminationTypeLambert
                             : illumination.Get<std::string>() == "null"  ? kQ3IlluminationTypeNULL
                                                                          : kQ3IlluminationTypePhong;
    }
    const int texture = pbr.baseColorTexture.index;
    if (texture >= 0 && std::size_t(texture) < model.textures.size()) {
        const tinygltf::Texture& t = model.textures[texture];
        if (t.source >= 0 && std::size_t(t.source) < model.images.size()) {
            if (images[t.source] < 0) {
                const tinygltf::Image& img = model.images[t.source];
                Image image;
                image.width = std::uint32_t(img.width);
                image.height = std::uint32_t(img.height);
                image.rgba = img.image;
                if (img.component != 4 || img.bits != 8 ||
                    image.rgba.size() != std::size_t(image.width) * image.height * 4)
                    fail(kQ3ErrorInvalidData, "image " + std::to_string(t.source) + " was not decoded");
                for (std::size_t i = 3; i < image.rgba.size(); i += 4)
                    image.hasAlpha = image.hasAlpha || image.rgba[i] != 255;
                images[t.source] = int(scene.images.size());
                scene.images.push_back(std::move(image));
            }
            m.image = images[t.source];
            if (t.sampler >= 0 && std::size_t(t.sampler) < model.samplers.size()) {
                m.uBoundary = boundaryOf(model.samplers[t.sampler].wrapS);
                m.vBoundary = boundaryOf(model.samplers[t.sampler].wrapT);
            }
        }
    }
    return m;
}

} // namespace

Scene readGltf(const std::string& path)
{
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
        fail(kQ3ErrorFileNotOpen, "cannot open " + path);
    char magic[4] = {};
    probe.read(magic, 4);
    probe.close();
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                           : loader.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!ok) {
        while (!err.empty() && err.back() == '\n')
            err.pop_back();
        fail(kQ3ErrorInvalidData, path + " is not a glTF 2.0 file Q3 can read: " + (err.empty() ? "no detail" : err));
    }
    for (const std::string& required : model.extensionsRequired)
        if (required != kUnlit && required != kTextureTransform)
            fail(kQ3ErrorUnsupportedFunctionality, path + " requires the extension " + required + ", which Q3 does not read");

    Scene scene;
    std::vector<int> images(model.images.size(), -1);
    std::vector<int> materials(model.materials.size() + 1, -1);
    for (const tinygltf::Mesh& mesh : model.meshes) {
        Mesh out;
        out.name = mesh.name;
        for (const tinygltf::Primitive& p : mesh.primitives) {
            Primitive prim;
            const auto position = p.attributes.find("POSITION");
            if (position == p.attributes.end())
                continue;
            prim.positions = readFloats(model, position->second, 3, "POSITION");
            const std::size_t count = prim.positions.size() / 3;
            if (auto a = p.attributes.find("NORMAL"); a != p.attributes.end())
                prim.normals = readFloats(model, a->second, 3, "NORMAL");
            if (auto a = p.attributes.find("TEXCOORD_0"); a != p.attributes.end()) {
                prim.uvs = readFloats(model, a->second, 2, "TEXCOORD_0");
                if (p.material >= 0 && std::size_t(p.material) < model.materials.size())
                    applyTextureTransform(model.materials[p.material].pbrMetallicRoughness.baseColorTexture, prim.uvs);
                for (std::size_t i = 1; i < prim.uvs.size(); i += 2)
                    prim.uvs[i] = 1.0f - prim.uvs[i];
            }
            if (auto a = p.attributes.find("COLOR_0"); a != p.attributes.end())
                prim.colors = readFloats(model, a->second, 4, "COLOR_0");
            std::vector<std::uint32_t> indices;
            if (p.indices >= 0)
                indices = readIndices(model, p.indices, count);
            else
                for (std::uint32_t i = 0; i < count; ++i)
                    indices.push_back(i);
            switch (p.mode) {
            case TINYGLTF_MODE_TRIANGLES:
            case TINYGLTF_MODE_TRIANGLE_STRIP:
            case TINYGLTF_MODE_TRIANGLE_FAN:
                prim.mode = Primitive::Mode::kTriangles;
                prim.indices = triangulate(p.mode, indices);
                break;
            case TINYGLTF_MODE_LINE_STRIP:
            case TINYGLTF_MODE_LINE_LOOP:
                prim.mode = Primitive::Mode::kLineStrip;
                prim.indices = indices;
                if (p.mode == TINYGLTF_MODE_LINE_LOOP && !indices.empty())
                    prim.indices.push_back(indices.front());
                break;
            case TINYGLTF_MODE_LINE:
                prim.mode = Primitive::Mode::kLines;
                prim.indices = indices;
                break;
            default:
                prim.mode = Primitive::Mode::kPoints;
                prim.indices = indices;
                break;
            }
            const int key = p.material + 1;
            if (key < 0 || std::size_t(key) >= materials.size())
                fail(kQ3ErrorInvalidData, "a primitive refers to no material");
            if (materials[key] < 0) {
                materials[key] = int(scene.materials.size());
                scene.materials.push_back(materialOf(model, p.material, scene, images));
            }
            prim.material = materials[key];
            out.primitives.push_back(std::move(prim));
        }
        scene.meshes.push_back(std::move(out));
    }
    for (const tinygltf::Camera& c : model.cameras) {
        Camera out;
        out.perspective = c.type != "orthographic";
        if (out.perspective) {
            out.yfov = c.perspective.yfov;
            out.aspect = c.perspective.aspectRatio > 0.0 ? c.perspective.aspectRatio : 1.0;
            out.znear = c.perspective.znear;
            out.zfar = c.perspective.zfar;
        } else {
            out.xmag = c.orthographic.xmag;
            out.ymag = c.orthographic.ymag;
            out.znear = c.orthographic.znear;
            out.zfar = c.orthographic.zfar;
        }
        scene.cameras.push_back(out);
    }
    for (const tinygltf::Light& l : model.lights) {
        Light out;
        out.kind = l.type == "directional" ? Light::Kind::kDirectional
                   : l.type == "spot"      ? Light::Kind::kSpot
                                           : Light::Kind::kPoint;
        if (l.color.size() == 3)
            out.color = TQ3ColorRGB{float(l.color[0]), float(l.color[1]), float(l.color[2])};
        out.intensity = float(l.intensity);
        out.innerCone = l.spot.innerConeAngle;
        out.outerCone = l.spot.outerConeAngle;
        scene.lights.push_back(out);
    }
    for (const tinygltf::Node& n : model.nodes) {
        Node out;
        out.name = n.name;
        out.mesh = n.mesh;
        if (n.camera >= 0 && std::size_t(n.camera) < scene.cameras.size())
            out.camera = n.camera;
        const auto light = n.extensions.find("KHR_lights_punctual");
        if (light != n.extensions.end() && light->second.Get("light").IsInt()) {
            const int index = light->second.Get("light").Get<int>();
            if (index >= 0 && std::size_t(index) < scene.lights.size())
                out.light = index;
        }
        out.children = n.children;
        out.matrix = matrixOf(n);
        out.hasMatrix = out.matrix != Node{}.matrix;
        scene.nodes.push_back(out);
    }
    for (const Node& n : scene.nodes)
        for (int child : n.children)
            if (child < 0 || std::size_t(child) >= scene.nodes.size())
                fail(kQ3ErrorInvalidData, path + ": a node's child does not exist");
    if (!model.scenes.empty()) {
        const int which = model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size()
                              ? model.defaultScene
                              : 0;
        scene.roots = model.scenes[which].nodes;
    }
    for (int root : scene.roots)
        if (root < 0 || std::size_t(root) >= scene.nodes.size())
            fail(kQ3ErrorInvalidData, path + ": a scene's node does not exist");
    return scene;
}

} // namespace q3::exchange

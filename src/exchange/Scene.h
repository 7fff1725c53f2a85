// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A model between Q3 and a foreign file format: plain values only, no Q3
// objects, so that each format's writer and reader only translates this
// description (Filament's split of "what to draw" from "how a backend draws
// it"). SceneExport fills it from a group; SceneImport builds Q3 objects from
// it.

#include "QD3D.h"
#include "QD3DShader.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace q3::exchange {

/// An image, 8 bits per channel, RGBA, top row first.
struct Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    /// Whether any pixel's alpha is below 255 (a texture with alpha).
    bool hasAlpha = false;
    std::vector<unsigned char> rgba;
};

/// A surface's look: QuickDraw 3D's attributes and illumination shader.
struct Material {
    TQ3ColorRGB diffuse{1.0f, 1.0f, 1.0f};
    /// The transparency colour's mean: 1 opaque.
    float alpha = 1.0f;
    TQ3ColorRGB specular{0.5f, 0.5f, 0.5f};
    float specularControl = 4.0f;
    /// kQ3IlluminationTypePhong, Lambert, NULL (unlit), or 0 (none submitted:
    /// unlit, as QuickDraw 3D draws then).
    TQ3ObjectType illumination = 0;
    /// Index into Scene::images, or -1.
    int image = -1;
    TQ3ShaderUVBoundary uBoundary = kQ3ShaderUVBoundaryWrap;
    TQ3ShaderUVBoundary vBoundary = kQ3ShaderUVBoundaryWrap;
    /// Whether the vertex colours (Primitive::colors) replace the diffuse
    /// colour.
    bool vertexColors = false;

    bool operator==(const Material& other) const;
};

/// One primitive of a mesh. Attribute arrays are empty or hold one entry
/// per vertex. uvs are QuickDraw 3D's: v runs up from the image's bottom row.
struct Primitive {
    enum class Mode { kTriangles, kLineStrip, kLines, kPoints };
    Mode mode = Mode::kTriangles;
    std::vector<float> positions; ///< x y z
    std::vector<float> normals;   ///< x y z, unit length
    std::vector<float> uvs;       ///< u v
    std::vector<float> colors;    ///< r g b a
    std::vector<std::uint32_t> indices;
    int material = -1;
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

/// A camera: perspective (fieldOfView > 0, radians, vertical) or
/// orthographic (xmag, ymag half widths).
struct Camera {
    bool perspective = true;
    double yfov = 1.0;
    double aspect = 1.0;
    double xmag = 1.0;
    double ymag = 1.0;
    double znear = 0.1;
    double zfar = 100.0;
};

/// A light of KHR_lights_punctual; it shines down its node's -z axis.
struct Light {
    enum class Kind { kDirectional, kPoint, kSpot };
    Kind kind = Kind::kPoint;
    TQ3ColorRGB color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;
    double innerCone = 0.0;
    double outerCone = 0.785398;
};

/// A node. matrix is QuickDraw 3D's row-vector matrix, value[row][column]
/// flattened row by row: p' = p * matrix.
struct Node {
    std::string name;
    bool hasMatrix = false;
    std::array<double, 16> matrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    int mesh = -1;
    int camera = -1;
    int light = -1;
    std::vector<int> children;
};

struct Scene {
    std::vector<Image> images;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    std::vector<Node> nodes;
    std::vector<int> roots;
};

/// QuickDraw 3D's specular control (a Phong exponent) as glTF's roughness and
/// back: the Blinn-Phong exponent n matches a Beckmann distribution of slope
/// alpha = sqrt(2 / (n + 2)) (Walter et al., "Microfacet Models for
/// Refraction", EGSR 2007, section 5.2), and glTF's roughness is
/// sqrt(alpha).
double roughnessFromSpecularControl(double control);
double specularControlFromRoughness(double roughness);

} // namespace q3::exchange

// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "exchange/Exchange.h"

#include "core/Error.h"
#include "exchange/AssimpFormats.h"
#include "exchange/Gltf.h"
#include "exchange/SceneImport.h"
#include "group/Group.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace q3::exchange {

namespace {

std::string extensionOf(const std::string& path)
{
    const std::size_t dot = path.find_last_of('.');
    const std::size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot + 1);
    for (char& c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

} // namespace

TQ3ExchangeFormat formatFor(TQ3ExchangeFormat requested, const std::string& path)
{
    switch (requested) {
    case kQ3ExchangeFormatGLTF:
    case kQ3ExchangeFormatGLB:
    case kQ3ExchangeFormatOBJ:
    case kQ3ExchangeFormatSTL:
        return requested;
    case kQ3ExchangeFormatAny:
        break;
    default:
        fail(kQ3ErrorInvalidParameter, "format " + std::to_string(long(requested)) + " is not a TQ3ExchangeFormat");
    }
    const std::string ext = extensionOf(path);
    if (ext == "gltf")
        return kQ3ExchangeFormatGLTF;
    if (ext == "glb")
        return kQ3ExchangeFormatGLB;
    if (ext == "obj")
        return kQ3ExchangeFormatOBJ;
    if (ext == "stl")
        return kQ3ExchangeFormatSTL;
    fail(kQ3ErrorInvalidParameter, "the extension of " + path + " names no format Q3 writes (.gltf, .glb, .obj, .stl)");
}

namespace {

// An OBJ's files go to a temporary directory beside the target, then are
// renamed into place, the .obj last, so that a reader never finds an .obj
// whose material file or textures are not there yet.
void writeObjFiles(const Scene& scene, const std::string& path)
{
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string stem = target.stem().string();
    const fs::path temporary = fs::path(path + ".q3tmp" + std::to_string(long(::getpid())));
    std::error_code code;
    if (!fs::create_directory(temporary, code))
        fail(kQ3ErrorFileNotOpen, "cannot write " + path);
    try {
        writeObj(scene, temporary.string(), stem);
        std::vector<fs::path> files;
        for (const fs::directory_entry& entry : fs::directory_iterator(temporary))
            files.push_back(entry.path());
        std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
            return (a.extension() == ".obj") < (b.extension() == ".obj");
        });
        for (const fs::path& file : files) {
            const fs::path to = file.extension() == ".obj" ? target : directory / file.filename();
            fs::rename(file, to, code);
            if (code)
                fail(kQ3ErrorFileNotOpen, "cannot write " + to.string());
        }
    } catch (...) {
        fs::remove_all(temporary, code);
        throw;
    }
    fs::remove_all(temporary, code);
}

} // namespace

void writeFile(const Object& object, const std::string& path, TQ3ExchangeFormat format,
               const SubdivisionChoice& subdivision)
{
    const TQ3ExchangeFormat chosen = formatFor(format, path);
    const Scene scene = sceneFrom(object, subdivision);
    if (chosen == kQ3ExchangeFormatOBJ) {
        writeObjFiles(scene, path);
        return;
    }
    // Beside the target, so that the rename stays on one file system.
    const std::string temporary = path + ".q3tmp" + std::to_string(long(::getpid()));
    try {
        if (chosen == kQ3ExchangeFormatSTL)
            writeStl(scene, temporary);
        else
            writeGltf(scene, temporary, chosen == kQ3ExchangeFormatGLB);
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        fail(kQ3ErrorFileNotOpen, "cannot write " + path);
    }
}

Ref<DisplayGroup> readFile(const std::string& path, TQ3ExchangeFormat format)
{
    if (format < kQ3ExchangeFormatAny || format > kQ3ExchangeFormatSTL)
        fail(kQ3ErrorInvalidParameter, "format " + std::to_string(long(format)) + " is not a TQ3ExchangeFormat");
    const std::string ext = extensionOf(path);
    const bool assimp = format == kQ3ExchangeFormatOBJ || format == kQ3ExchangeFormatSTL ||
                        (format == kQ3ExchangeFormatAny && (ext == "obj" || ext == "stl"));
    return groupFrom(assimp ? readWithAssimp(path) : readGltf(path));
}

} // namespace q3::exchange

// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "exchange/Exchange.h"

#include "core/Error.h"
#include "exchange/Gltf.h"
#include "exchange/SceneImport.h"
#include "group/Group.h"

#include <cctype>
#include <cstdio>
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
    fail(kQ3ErrorInvalidParameter, "the extension of " + path + " names no format Q3 writes (.gltf, .glb)");
}

void writeFile(const Object& object, const std::string& path, TQ3ExchangeFormat format,
               const SubdivisionChoice& subdivision)
{
    const TQ3ExchangeFormat chosen = formatFor(format, path);
    const Scene scene = sceneFrom(object, subdivision);
    // Beside the target, so that the rename stays on one file system.
    const std::string temporary = path + ".q3tmp" + std::to_string(long(::getpid()));
    try {
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
    if (format != kQ3ExchangeFormatAny && format != kQ3ExchangeFormatGLTF && format != kQ3ExchangeFormatGLB)
        fail(kQ3ErrorInvalidParameter, "format " + std::to_string(long(format)) + " is not a TQ3ExchangeFormat");
    return groupFrom(readGltf(path));
}

} // namespace q3::exchange

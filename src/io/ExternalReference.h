// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// External references (QuickDraw 3D 1.5, "External Reference Objects"): an
// object of another metafile, named by that file's path and the reference
// ID its table of contents gives the object:
//
//   Container ( ExternalReference ( refID ) CString ( "path" ) )
//
// Binary tags 'rfex' and 'strc'. Q3File_MarkAsExternalReference marks an
// object read from a Unix path file (with a table of contents entry) so that
// every later write of it, to any file, is such a reference; reading one
// reads the object from the other file.

#include "core/Object.h"
#include "io/ClassIO.h"
#include "io/Metafile.h"

#include <cstdint>
#include <string>
#include <vector>

namespace q3::io {

constexpr TQ3ObjectType kTypeExternalReference = Q3_OBJECT_TYPE('r', 'f', 'e', 'x');
constexpr TQ3ObjectType kTypeCString = Q3_OBJECT_TYPE('s', 't', 'r', 'c');

/// Marks `object` as written as an external reference to `refId` of the file
/// at `path`, until forgetExternals(owner) (its file object's end). The
/// object is kept alive meanwhile.
void markExternal(const SharedObject& object, const std::string& path, std::uint32_t refId, const void* owner);
void forgetExternals(const void* owner);
/// Whether the object is marked; its reference if so.
bool externalMark(const Object& object, std::string& path, std::uint32_t& refId);

/// Writes the external reference container.
void writeExternalReference(Encoder& out, const std::string& path, std::uint32_t refId);

/// The path of every external reference in the file, in file order (one per
/// reference, repeats included).
std::vector<std::string> externalReferencePaths(const Metafile& file);

/// The ExternalReference and CString classes' rows.
void addExternalReferenceClasses(std::vector<ClassIO>& table);

} // namespace q3::io

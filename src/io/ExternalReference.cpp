// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/ExternalReference.h"

#include "core/Error.h"
#include "core/Limits.h"
#include "core/ThreadLocal.h"
#include "io/StringObject.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>

namespace q3::io {

namespace {

struct Mark {
    Ref<SharedObject> object;
    std::string path;
    std::uint32_t refId;
    const void* owner;
};

// Marks outlive the read that made them and apply to writes to any file, so
// they live here, keyed by object, removed with their file object.
struct Marks {
    std::mutex mutex;
    std::map<const Object*, Mark> byObject;
};

Marks& marks()
{
    static Marks* instance = new Marks; // never destroyed: files may end during exit
    return *instance;
}

// External files being read, outermost first, to refuse a file that refers
// back to one being read (a cycle) and too long a chain.
struct OpeningTag;
std::vector<std::string>& opening()
{
    return threadLocal<std::vector<std::string>, OpeningTag>();
}
constexpr std::size_t kMaxExternalNesting = 8;

std::string textOf(ReadContext& context, const Node& node)
{
    DataReader in = context.reader(node);
    std::string text = in.string();
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a CString has data after its string");
    return text;
}

Ref<SharedObject> readCString(ReadContext& context, const Parts& parts)
{
    return Ref<SharedObject>(makeShared<CString>(textOf(context, parts.root)));
}

void writeCString(WriteContext& context, const Object& object)
{
    Encoder& out = context.out();
    out.begin(kTypeCString, "CString");
    out.string(static_cast<const CString&>(object).text());
    out.end();
}

// Reads the object `refId` of the metafile at `path` (relative paths from
// the directory of the file being read, when that is a path).
Ref<SharedObject> readExternalReference(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const std::uint32_t refId = in.u32();
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "an ExternalReference has data after its reference ID");
    const Node* name = parts.find(kTypeCString);
    if (name == nullptr)
        fail(kQ3ErrorInvalidMetafileObject, "an ExternalReference without the CString naming its file");
    std::filesystem::path path(textOf(context, *name));
    if (path.empty())
        fail(kQ3ErrorInvalidMetafileObject, "an ExternalReference names no file");
    if (path.is_relative() && !context.baseDirectory().empty())
        path = std::filesystem::path(context.baseDirectory()) / path;
    const std::string where = path.lexically_normal().string();
    for (const std::string& open : opening())
        if (open == where)
            fail(kQ3ErrorInvalidMetafileObject,
                 "an external reference to " + where + ", which is being read (a cycle)");
    if (opening().size() >= kMaxExternalNesting)
        fail(kQ3ErrorInvalidMetafileObject, "external references nest deeper than " +
                                                std::to_string(kMaxExternalNesting) + " files");
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        fail(kQ3ErrorInvalidMetafileObject, "an external reference to " + where + ", which is not a file");
    const auto size = std::filesystem::file_size(path, error);
    if (error || size > limits::kMaxStorageBytes)
        fail(kQ3ErrorInvalidMetafileObject, "the file " + where + " an external reference names cannot be read");
    std::ifstream stream(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
    if (!stream.good() && !stream.eof())
        fail(kQ3ErrorInvalidMetafileObject, "the file " + where + " an external reference names cannot be read");

    opening().push_back(where);
    try {
        std::unique_ptr<Metafile> other = parse(std::move(bytes), &typeOfName);
        const auto found = other->references.find(refId);
        if (found == other->references.end())
            fail(kQ3ErrorInvalidMetafileObject, "an external reference to object " + std::to_string(refId) + " of " +
                                                    where + ", whose table of contents has no such object");
        ReadContext otherContext(*other);
        otherContext.setBaseDirectory(path.parent_path().string());
        Ref<SharedObject> result = otherContext.object(*found->second);
        opening().pop_back();
        return result;
    } catch (...) {
        opening().pop_back();
        throw;
    }
}

void collectPaths(const Metafile& file, const std::vector<Node>& nodes, std::vector<std::string>& paths)
{
    for (const Node& node : nodes) {
        if (node.type == kTypeContainer && !node.children.empty() &&
            node.children.front().type == kTypeExternalReference) {
            for (std::size_t i = 1; i < node.children.size(); ++i)
                if (node.children[i].type == kTypeCString) {
                    try {
                        paths.push_back(DataReader(file, node.children[i]).string());
                    } catch (...) {
                        // A malformed name is reported when the reference is read.
                    }
                    break;
                }
            continue;
        }
        collectPaths(file, node.children, paths);
    }
}

} // namespace

void markExternal(const SharedObject& object, const std::string& path, std::uint32_t refId, const void* owner)
{
    Marks& all = marks();
    std::lock_guard<std::mutex> lock(all.mutex);
    all.byObject[&object] =
        Mark{Ref<SharedObject>::retain(const_cast<SharedObject*>(&object)), path, refId, owner};
}

void forgetExternals(const void* owner)
{
    std::vector<Ref<SharedObject>> released; // released after the lock
    {
        Marks& all = marks();
        std::lock_guard<std::mutex> lock(all.mutex);
        for (auto it = all.byObject.begin(); it != all.byObject.end();) {
            if (it->second.owner == owner) {
                released.push_back(std::move(it->second.object));
                it = all.byObject.erase(it);
            } else {
                ++it;
            }
        }
    }
}

bool externalMark(const Object& object, std::string& path, std::uint32_t& refId)
{
    Marks& all = marks();
    std::lock_guard<std::mutex> lock(all.mutex);
    const auto found = all.byObject.find(&object);
    if (found == all.byObject.end())
        return false;
    path = found->second.path;
    refId = found->second.refId;
    return true;
}

void writeExternalReference(Encoder& out, const std::string& path, std::uint32_t refId)
{
    out.begin(kTypeContainer, "Container");
    out.begin(kTypeExternalReference, "ExternalReference");
    out.u32(refId);
    out.end();
    out.begin(kTypeCString, "CString");
    out.string(path);
    out.end();
    out.end();
}

std::vector<std::string> externalReferencePaths(const Metafile& file)
{
    std::vector<std::string> paths;
    collectPaths(file, file.objects, paths);
    return paths;
}

void addExternalReferenceClasses(std::vector<ClassIO>& table)
{
    table.push_back({kTypeExternalReference, "ExternalReference", readExternalReference,
                     [](WriteContext&, const Object&) {}});
    table.push_back({kQ3StringTypeCString, "CString", readCString, writeCString});
}

} // namespace q3::io

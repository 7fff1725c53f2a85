// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// One reader and one writer per class, found by the class's 3DMF type and
// text name. A class's 3DMF layout is its own (optional fields, attribute
// sets as child objects), so each class has a small pair of functions in its
// family's file (GeometryIO.cpp, AttributeIO.cpp, GroupIO.cpp, ...), listed
// there in one table; classes() gathers the tables. Adding a class is one
// read function, one write function and one table row; a simple geometry
// (a fixed sequence of its struct's fields, then subobjects) gets both from
// its data description and needs only the row (SimpleGeometryIO.cpp).

#include "core/AttributeSet.h"
#include "core/Object.h"
#include "core/Ref.h"
#include "io/Metafile.h"

#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace q3 {
class File;
class Group;
}

namespace q3::io {

class ReadContext;
class WriteContext;
class CustomWrite;

/// An object's parts as the file holds them: the object itself and, when it
/// is the root of a container, the objects after it (attribute sets, vertex
/// attribute set lists, caps...).
struct Parts {
    const Node& root;
    std::vector<const Node*> subobjects;
    const Metafile* file = nullptr; ///< to look through references
    /// The container's children (the root, then the subobjects), for a class
    /// that reads its subobjects as a sequence (groups included); null when
    /// the root stands alone.
    const std::vector<Node>* children = nullptr;

    /// The first subobject of that type (looking through containers), or null.
    const Node* find(TQ3ObjectType type) const;
};

struct ClassIO {
    TQ3ObjectType type;
    const char* name; ///< the text name
    Ref<SharedObject> (*read)(ReadContext& context, const Parts& parts);
    /// Writes the object (and its subobjects, in a container when it has
    /// any). `object` is of class `type`.
    void (*write)(WriteContext& context, const Object& object);
};

/// Every class Q3 reads and writes.
const std::vector<ClassIO>& classes();
const ClassIO* classOfType(TQ3ObjectType type);
/// The most derived class with an entry for the object (its class or the
/// nearest parent that has one), or null.
const ClassIO* classOfObject(const Object& object);
/// For the parser: the type a text name stands for, 0 for none.
TQ3ObjectType typeOfName(const std::string& name);

constexpr TQ3ObjectType kTypeDisplayGroupState = Q3_OBJECT_TYPE('d', 'g', 's', 't');
/// Sets a group's state from a DisplayGroupState node (GroupIO.cpp); a
/// state for a group that is no display group posts
/// kQ3WarningInvalidSubObjectForObject and is ignored.
void applyGroupState(ReadContext& context, SharedObject& group, const Node& state);
/// One object beside a group in its BeginGroup (GroupIO.cpp): its state is
/// applied, an unknown element is kept (kQ3WarningUnknownElementType) and
/// written back, anything else is left out with
/// kQ3WarningInvalidSubObjectForObject.
void readGroupSubobject(ReadContext& context, Group& group, const Node& node);

/// The family tables (one per file).
void addGeometryClasses(std::vector<ClassIO>& table);
/// The geometries whose reader and writer come from their data description
/// (Describe<S>::fileFields and fileParts), in SimpleGeometryIO.cpp;
/// addGeometryClasses adds them.
void addSimpleGeometryClasses(std::vector<ClassIO>& table);
/// The geometries with nested parts (patches with trim loops, polyhedra...),
/// in GeometryIOComplex.cpp; addGeometryClasses adds them.
void addComplexGeometryClasses(std::vector<ClassIO>& table);
void addAttributeClasses(std::vector<ClassIO>& table);
void addGroupClasses(std::vector<ClassIO>& table);
void addStateClasses(std::vector<ClassIO>& table);
/// Cameras and their placement, range and view port (CameraIO.cpp).
void addCameraClasses(std::vector<ClassIO>& table);
/// The pixmap marker (PixmapMarkerIO.cpp).
void addPixmapMarkerClasses(std::vector<ClassIO>& table);
/// ExternalReference and CString (ExternalReference.cpp).
void addExternalReferenceClasses(std::vector<ClassIO>& table);
/// ViewHints and its image subobjects (ViewHintsIO.cpp).
void addViewHintsClasses(std::vector<ClassIO>& table);
/// Pixmap and mipmap textures and the texture shader (TextureIO.cpp).
void addTextureClasses(std::vector<ClassIO>& table);

/// Reading one file: builds objects from nodes, resolving references once
/// each (so two references give one object) and refusing cycles.
class ReadContext {
public:
    explicit ReadContext(const Metafile& file) : m_file(file) {}

    const Metafile& file() const { return m_file; }
    DataReader reader(const Node& node) const { return DataReader(m_file, node); }
    /// Where relative paths of external references start: the directory of
    /// the file being read when it is a path, else empty (as written).
    const std::string& baseDirectory() const { return m_baseDirectory; }
    void setBaseDirectory(std::string directory) { m_baseDirectory = std::move(directory); }
    /// The reference ID the file's table of contents gives an object this
    /// context read, or 0 when it has none.
    std::uint32_t refIdOf(const Object& object) const;
    /// The file object reading (what custom classes' read methods read
    /// through), or null (an external reference's file).
    File* fileObject() const { return m_fileObject; }
    void setFileObject(File* file) { m_fileObject = file; }

    /// The object a node stands for: a container's root with its
    /// subobjects, a reference's target, an unknown object for a type no
    /// class has. Throws kQ3ErrorInvalidMetafileObject for a reference to
    /// nothing or to an object being read (a cycle), and past
    /// limits::kMaxMetafileNesting.
    Ref<SharedObject> object(const Node& node);
    /// As object(), checking the class: kQ3ErrorInvalidMetafileSubObject
    /// when it is not a T (`what` names it).
    template <class T>
    Ref<T> objectAs(const Node& node, const char* what)
    {
        Ref<SharedObject> any = object(node);
        if (!any->isType(T::kClassType))
            fail(kQ3ErrorInvalidMetafileSubObject, std::string(what) + " is a " + any->classInfo().name);
        return Ref<T>::adopt(static_cast<T*>(any.detach()));
    }
    /// The attribute set among the subobjects, or null.
    Ref<AttributeSet> attributeSet(const Parts& parts);

    /// Reads the objects of a sequence (a file's top level, a container's
    /// children) from `index`: one object, or a BeginGroup up to its
    /// EndGroup as one group. Advances index past what it read.
    Ref<SharedObject> sequenceItem(const std::vector<Node>& nodes, std::size_t& index);
    /// The (empty) group a BeginGroup node opens, with its state.
    Ref<SharedObject> groupOf(const Node& beginGroup);
    /// The group object a BeginGroup starts with (an unknown one: a display
    /// group keeping it, with a warning).
    Ref<SharedObject> groupObject(const Node& node);
    /// Applies the DisplayGroupState objects that stand first among a
    /// group's members (from `index`, before `end`) to the group; returns
    /// the index of the first member after them.
    std::size_t groupStateAfter(SharedObject& group, const std::vector<Node>& nodes, std::size_t index,
                                std::size_t end);

private:
    Ref<SharedObject> build(const Node& node);

    const Metafile& m_file;
    File* m_fileObject = nullptr;
    std::string m_baseDirectory;
    std::map<const Node*, Ref<SharedObject>> m_done;
    std::set<const Node*> m_reading;
    std::size_t m_depth = 0;
};

/// Writing one file. Objects written twice are written once and referred to
/// (unless `stream`). A `database` file lists every shared object it writes
/// in its table of contents, referred to or not (the 3D Metafile Reference's
/// Database flag), groups excepted: Q3 refers to no group.
class WriteContext {
public:
    WriteContext(Encoding encoding, bool stream, bool database = false)
        : m_out(encoding), m_stream(stream), m_database(database && !stream)
    {
    }

    Encoder& out() { return m_out; }
    /// Writes any object Q3 has a class for (references for repeats); an
    /// object of no such class posts kQ3WarningNoObjectSupportForWriteMethod
    /// and is left out.
    void object(const Object& object);
    /// Writes an object that lives only for this call (an immediate-mode
    /// geometry): never referred to.
    void temporary(const Object& object);
    /// Writes a non-empty attribute set (nothing for null or empty).
    void attributeSet(const AttributeSet* set);
    /// Whether a set would be written.
    static bool hasAttributes(const AttributeSet* set);

    std::vector<unsigned char> finish(TQ3FileMode mode);

    /// The handles custom classes' methods get: the view of the writing
    /// loop writing now, and the file (null once it is closed or gone: a
    /// write method cannot run then).
    void setView(TQ3ViewObject view) { m_view = view; }
    TQ3ViewObject view() const { return m_view; }
    void setFile(TQ3FileObject file) { m_fileHandle = file; }
    TQ3FileObject fileHandle() const { return m_fileHandle; }
    /// While a custom class's traverse method runs, what it submits is
    /// collected here (io/CustomIO.h) instead of being written.
    CustomWrite* collecting() const { return m_collecting; }
    CustomWrite* setCollecting(CustomWrite* collector) { return std::exchange(m_collecting, collector); }
    /// Custom methods running: the file cannot be closed meanwhile.
    bool busy() const { return m_methods > 0; }
    void enterMethod() { ++m_methods; }
    void leaveMethod() { --m_methods; }

private:
    /// Writes the object's own name and URL elements (groups and sets write
    /// theirs themselves) into the container of the object just written from
    /// `start`, making one when the object had none.
    void ownElements(const Object& object, std::size_t start);

    struct Written {
        std::size_t position;
        std::uint32_t id;   ///< its table of contents ID, 0 while nothing refers to it
        TQ3ObjectType type; ///< for its table of contents entry
        const char* name;
    };
    Encoder m_out;
    bool m_stream;
    bool m_database;
    TQ3ViewObject m_view = nullptr;
    TQ3FileObject m_fileHandle = nullptr;
    CustomWrite* m_collecting = nullptr;
    std::size_t m_methods = 0;
    std::map<const Object*, Written> m_written;
    /// A stream file's ExternalReference objects (each listed in the table
    /// of contents; nothing refers to them).
    std::vector<Written> m_streamExternals;
    std::vector<Ref<SharedObject>> m_keep;
    std::uint32_t m_nextId = 1;
    std::size_t m_depth = 0;
    /// What the submitted object being written added, to undo on failure.
    std::vector<const Object*> m_added;
    std::vector<const Object*> m_labelled;
};

/// Runs `body` inside a Container when `container` is true.
template <class Body>
void maybeContainer(WriteContext& context, bool container, Body&& body)
{
    if (container)
        context.out().begin(kTypeContainer, "Container");
    body();
    if (container)
        context.out().end();
}

} // namespace q3::io

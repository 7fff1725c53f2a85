// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DIO.h"
#include "core/Object.h"
#include "io/ClassIO.h"
#include "io/Metafile.h"
#include "base/Storage.h"
#include "view/View.h"

#include <functional>
#include <memory>

namespace q3 {

extern const ClassInfo kFileClass;
extern const ClassInfo kEndGroupClass;

/// What Q3File_ReadObject returns at the end of a group read object by
/// object (kQ3FileReadObjectsInGroup).
class EndGroup final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeEndGroup;
    const ClassInfo& classInfo() const override { return kEndGroupClass; }
    Object* duplicate() const override { return makeShared<EndGroup>().detach(); }
};

/// A QuickDraw 3D file object (QD3DIO.h): a storage and, while open, either
/// the parsed file being read or the objects being written. Invariant: open
/// exactly when m_state is not kClosed; while open the storage is marked in
/// use and m_storage does not change; reading holds a parsed file whose
/// every object is within its bounds (io::parse).
class File final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeFile;

    File() = default;
    ~File() override;

    const ClassInfo& classInfo() const override { return kFileClass; }
    /// Files cannot be duplicated (kQ3ErrorInvalidObjectType), as in QuickDraw 3D.
    Object* duplicate() const override;

    const Ref<Storage>& storage() const { return m_storage; }
    /// Throws kQ3ErrorFileIsOpen while open.
    void setStorage(Ref<Storage> storage);

    /// Parses the whole storage (kQ3ErrorFileAlreadyOpen,
    /// kQ3ErrorNoStorageSetForFile, the metafile errors); the mode read.
    TQ3FileMode openRead();
    void openWrite(TQ3FileMode mode);
    bool isOpen() const { return m_state != State::kClosed; }
    TQ3FileMode mode() const;
    TQ3FileVersion version() const;
    /// Writing: encodes everything written and puts it into the storage.
    void close();
    void cancel();

    /// Reading (each throws kQ3ErrorFileNotOpen unless open for reading).
    TQ3ObjectType nextObjectType() const;
    bool isNextObjectOfType(TQ3ObjectType type) const;
    Ref<SharedObject> readObject();
    void skipObject();
    bool isEndOfFile() const;

    /// What a writing loop of `view` writes to (kQ3ErrorFileNotOpen unless
    /// open for writing). The view's handle is what the traverse methods of
    /// custom classes get.
    std::shared_ptr<WriteTarget> writeTarget(TQ3ViewObject view);

    /// Runs `body` (a custom class's read or read-data method) with primitive
    /// reads reading `node`'s data (a container: its root's), and
    /// ReadObject, SkipObject and the end tests going through the
    /// container's subobjects and no further (the end of the file past
    /// them). What primitive reads were reading before comes back after.
    /// Returns the index among the container's children of the first
    /// subobject `body` neither read nor skipped (0 for a lone object).
    std::size_t readNode(const io::Node& node, const std::function<void()>& body);

    /// Primitive reads (Q3Uns32_Read, ...) read the data of one object in
    /// order: the object a primitive read started on, which is then consumed
    /// (a container: its root's data, and ReadObject / SkipObject go through
    /// its subobjects until isEndOfContainer()). `read` runs on the reader
    /// with room for `bytes` (binary) or `tokens` (text) checked first
    /// (kQ3ErrorReadMoreThanSize); a failed read leaves the position as it
    /// was. Throws kQ3ErrorReadStateInactive unless open for reading,
    /// kQ3ErrorEndOfFile when no object is left, kQ3ErrorInvalidMetafileObject
    /// for an object without data of its own (a group, a reference).
    template <class Read>
    auto readPrimitive(std::size_t bytes, std::size_t tokens, const char* what, Read&& read)
    {
        io::DataReader& in = dataReader();
        if (in.remaining() < (m_file->encoding == io::Encoding::kText ? tokens : bytes))
            dataEnds(what);
        const std::size_t at = in.tell();
        try {
            return read(in);
        } catch (...) {
            in.seek(at);
            throw;
        }
    }
    /// Whether the data primitive reads read are all read (see
    /// readPrimitive; before the first read, the next object's data).
    bool isEndOfData() const;
    /// False while the container primitive reads started on has subobjects
    /// left.
    bool isEndOfContainer() const;
    /// Where primitive writes go: the file at the point writing has reached
    /// (kQ3ErrorWriteStateInactive unless open for writing).
    io::Encoder& dataWriter();

    /// Q3File_MarkAsExternalReference: from now on, until this file object
    /// ends, every write of `object` (to any file) is an external reference
    /// to it in this file. Throws kQ3ErrorFileNotOpen unless open for
    /// reading, kQ3ErrorInvalidParameter when the storage is not a Unix path
    /// or the object is not one read from this file with a table of contents
    /// entry.
    void markAsExternalReference(const SharedObject& object);
    /// Q3File_GetExternalReferences: one C string object per external
    /// reference in the file, in file order, in a group; null when it has
    /// none. Throws kQ3ErrorFileNotOpen unless open for reading.
    Ref<SharedObject> externalReferences() const;

    /// Q3File_SetIdleMethod: called once before each object read or written.
    void setIdleMethod(TQ3FileIdleMethod method, const void* data);

    /// Q3File_SetReadInGroup: kQ3FileReadWholeGroup or
    /// kQ3FileReadObjectsInGroup (kQ3ErrorInvalidParameter otherwise).
    void setReadInGroup(TQ3FileReadGroupState state);
    /// The mode, with kQ3FileCurrentlyInsideGroup while a group read object
    /// by object is not finished.
    TQ3FileReadGroupState readInGroup() const;

    /// The idle method and its data, shared with writing loops' targets.
    struct Idle {
        TQ3FileIdleMethod method = nullptr;
        const void* data = nullptr;
        TQ3FileObject file = nullptr;
        /// False when the method asks to cancel.
        bool proceed() const { return method == nullptr || method(file, data) != kQ3Failure; }
    };

private:
    enum class State { kClosed, kReading, kWriting };
    /// The object primitive reads are reading.
    struct DataState {
        const io::Node* container = nullptr; ///< null for a plain object
        std::size_t nextChild = 1;
        std::unique_ptr<io::DataReader> reader;
        /// A custom class's method reads this object (readNode): nothing
        /// past it.
        bool scoped = false;
        bool childrenLeft() const { return container != nullptr && nextChild < container->children.size(); }
    };
    void requireReading() const;
    void release();
    io::DataReader& dataReader();
    [[noreturn]] void dataEnds(const char* what) const;
    void idleBeforeReading() const;
    TQ3ObjectType typeOfNode(const io::Node& node) const;

    Ref<Storage> m_storage;
    State m_state = State::kClosed;
    TQ3FileMode m_mode = kQ3FileModeNormal;
    std::unique_ptr<io::Metafile> m_file;
    std::unique_ptr<io::ReadContext> m_reader;
    std::size_t m_next = 0;
    TQ3FileReadGroupState m_readGroup = kQ3FileReadWholeGroup;
    std::size_t m_openGroups = 0; ///< groups being read object by object
    std::shared_ptr<io::WriteContext> m_writer;
    std::unique_ptr<DataState> m_data;
    std::shared_ptr<Idle> m_idle = std::make_shared<Idle>();
    /// Custom read methods running (readNode): the file cannot close then.
    std::size_t m_methods = 0;
};

} // namespace q3

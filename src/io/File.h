// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DIO.h"
#include "core/Object.h"
#include "io/ClassIO.h"
#include "io/Metafile.h"
#include "io/Storage.h"
#include "view/View.h"

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

    /// What a writing loop writes to (kQ3ErrorFileNotOpen unless open for
    /// writing).
    std::shared_ptr<WriteTarget> writeTarget();

    /// Q3File_SetReadInGroup: kQ3FileReadWholeGroup or
    /// kQ3FileReadObjectsInGroup (kQ3ErrorInvalidParameter otherwise).
    void setReadInGroup(TQ3FileReadGroupState state);
    /// The mode, with kQ3FileCurrentlyInsideGroup while a group read object
    /// by object is not finished.
    TQ3FileReadGroupState readInGroup() const;

private:
    enum class State { kClosed, kReading, kWriting };
    void requireReading() const;
    void release();

    Ref<Storage> m_storage;
    State m_state = State::kClosed;
    TQ3FileMode m_mode = kQ3FileModeNormal;
    std::unique_ptr<io::Metafile> m_file;
    std::unique_ptr<io::ReadContext> m_reader;
    std::size_t m_next = 0;
    TQ3FileReadGroupState m_readGroup = kQ3FileReadWholeGroup;
    std::size_t m_openGroups = 0; ///< groups being read object by object
    std::shared_ptr<io::WriteContext> m_writer;
};

} // namespace q3

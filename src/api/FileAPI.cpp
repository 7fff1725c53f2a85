// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DIO.h"

#include "api/Entry.h"
#include "io/File.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

TQ3FileObject Q3File_New(void)
{
    return guard(__func__, TQ3FileObject{nullptr}, []() -> TQ3FileObject { return makeShared<File>().detach(); });
}

TQ3Status Q3File_GetStorage(TQ3FileObject theFile, TQ3StorageObject* storage)
{
    return getHeld(__func__, theFile, "theFile", storage, "storage", &File::storage);
}

TQ3Status Q3File_SetStorage(TQ3FileObject theFile, TQ3StorageObject storage)
{
    return setHeldOptional(__func__, theFile, "theFile", storage, "storage", &File::setStorage);
}

TQ3Status Q3File_OpenRead(TQ3FileObject theFile, TQ3FileMode* mode)
{
    return guardStatus(__func__, [&] {
        const TQ3FileMode opened = lookup<File>(theFile, "theFile").openRead();
        if (mode != nullptr)
            *mode = opened;
    });
}

TQ3Status Q3File_OpenWrite(TQ3FileObject theFile, TQ3FileMode mode)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").openWrite(mode); });
}

TQ3Status Q3File_IsOpen(TQ3FileObject theFile, TQ3Boolean* isOpen)
{
    return guardStatus(__func__, [&] {
        readInto<File>(theFile, "theFile", isOpen, "isOpen",
                       [](const File& file) { return file.isOpen() ? kQ3True : kQ3False; });
    });
}

TQ3Status Q3File_GetMode(TQ3FileObject theFile, TQ3FileMode* mode)
{
    return guardStatus(__func__, [&] {
        readInto<File>(theFile, "theFile", mode, "mode", [](const File& file) { return file.mode(); });
    });
}

TQ3Status Q3File_GetVersion(TQ3FileObject theFile, TQ3FileVersion* version)
{
    return guardStatus(__func__, [&] {
        readInto<File>(theFile, "theFile", version, "version", [](const File& file) { return file.version(); });
    });
}

TQ3Status Q3File_Close(TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").close(); });
}

TQ3Status Q3File_Cancel(TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").cancel(); });
}

TQ3Status Q3View_StartWriting(TQ3ViewObject view, TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] {
        View& target = lookup<View>(view, "view");
        File& file = lookup<File>(theFile, "theFile");
        target.startWriting(file.writeTarget(view));
    });
}

TQ3ViewStatus Q3View_EndWriting(TQ3ViewObject view)
{
    return guard(__func__, kQ3ViewStatusError, [&] { return lookup<View>(view, "view").endWriting(); });
}

TQ3ObjectType Q3File_GetNextObjectType(TQ3FileObject theFile)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookup<File>(theFile, "theFile").nextObjectType(); });
}

TQ3Boolean Q3File_IsNextObjectOfType(TQ3FileObject theFile, TQ3ObjectType ofType)
{
    return guard(__func__, kQ3False, [&] {
        return lookup<File>(theFile, "theFile").isNextObjectOfType(ofType) ? kQ3True : kQ3False;
    });
}

TQ3Object Q3File_ReadObject(TQ3FileObject theFile)
{
    return guard(__func__, TQ3Object{nullptr},
                 [&]() -> TQ3Object { return lookup<File>(theFile, "theFile").readObject().detach(); });
}

TQ3Status Q3File_SkipObject(TQ3FileObject theFile)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").skipObject(); });
}

TQ3Boolean Q3File_IsEndOfFile(TQ3FileObject theFile)
{
    return guard(__func__, kQ3False,
                 [&] { return lookup<File>(theFile, "theFile").isEndOfFile() ? kQ3True : kQ3False; });
}

TQ3Status Q3File_SetReadInGroup(TQ3FileObject theFile, TQ3FileReadGroupState readGroupState)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").setReadInGroup(readGroupState); });
}

TQ3Status Q3File_GetReadInGroup(TQ3FileObject theFile, TQ3FileReadGroupState* readGroupState)
{
    return guardStatus(__func__, [&] {
        readInto<File>(theFile, "theFile", readGroupState, "readGroupState",
                       [](const File& file) { return file.readInGroup(); });
    });
}

TQ3Boolean Q3File_IsEndOfData(TQ3FileObject theFile)
{
    return guard(__func__, kQ3False,
                 [&] { return lookup<File>(theFile, "theFile").isEndOfData() ? kQ3True : kQ3False; });
}

TQ3Boolean Q3File_IsEndOfContainer(TQ3FileObject theFile, TQ3Object /*rootObject*/)
{
    return guard(__func__, kQ3False,
                 [&] { return lookup<File>(theFile, "theFile").isEndOfContainer() ? kQ3True : kQ3False; });
}

TQ3Status Q3File_SetIdleMethod(TQ3FileObject theFile, TQ3FileIdleMethod idle, const void* idleData)
{
    return guardStatus(__func__, [&] { lookup<File>(theFile, "theFile").setIdleMethod(idle, idleData); });
}

TQ3Status Q3File_MarkAsExternalReference(TQ3FileObject theFile, TQ3SharedObject sharedObject)
{
    return guardStatus(__func__, [&] {
        File& file = lookup<File>(theFile, "theFile");
        const SharedObject& object = lookup<SharedObject>(sharedObject, "sharedObject");
        file.markAsExternalReference(object);
    });
}

TQ3GroupObject Q3File_GetExternalReferences(TQ3FileObject theFile)
{
    return guard(__func__, TQ3GroupObject{nullptr}, [&]() -> TQ3GroupObject {
        return lookup<File>(theFile, "theFile").externalReferences().detach();
    });
}

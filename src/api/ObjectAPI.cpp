// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3D.h"
#include "QD3DIO.h"
#include "api/Entry.h"
#include "core/LargeBlocks.h"
#include "base/RenderTarget.h"
#include "io/ClassIO.h"
#include "io/CustomElements.h"
#include "io/File.h"
#include "view/View.h"
#include "controller/Controller.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3Status Q3Initialize(void)
{
    errors::beginCall();
    // At program start, before the application's threads use the environment.
    initializeRenderBackend();
    if (!system::initialize())
        errors::postNotice(kQ3NoticeSystemAlreadyInitialized,
                           "Q3Initialize: already initialized; the call nests and needs its own Q3Exit");
    try {
        // Apple's name and URL element classes (QD3DCustomElements.h), so
        // their names are registered before any file is read.
        io::registerCustomElements();
    } catch (const std::exception&) {
        errors::postError(kQ3ErrorOutOfMemory, "Q3Initialize: the custom element classes cannot be registered");
        return kQ3Failure;
    }
    return kQ3Success;
}

TQ3Status Q3Exit(void)
{
    return guardStatus(__func__, [] {
        system::exit();
        if (!system::isInitialized()) {
            memory::releaseKept();
            controllers::forgetAll();
        }
        const unsigned long live = liveObjectCount();
        if (!system::isInitialized() && live != 0)
            errors::postWarning(kQ3WarningPossibleMemoryLeak,
                                "Q3Exit: " + std::to_string(live) + " object(s) were never disposed");
    });
}

TQ3Boolean Q3IsInitialized(void)
{
    errors::beginCall();
    return system::isInitialized() ? kQ3True : kQ3False;
}

TQ3Status Q3GetVersion(unsigned long* majorRevision, unsigned long* minorRevision)
{
    return guardStatus(__func__, [&] {
        requireNonNull(majorRevision, "majorRevision");
        requireNonNull(minorRevision, "minorRevision");
        *majorRevision = 1;
        *minorRevision = 6;
    });
}

TQ3Status Q3GetReleaseVersion(unsigned long* releaseRevision)
{
    return guardStatus(__func__, [&] {
        requireNonNull(releaseRevision, "releaseRevision");
        *releaseRevision = 0x01608000ul; // 'vers' layout: 1.6.0, final stage, build 0
    });
}

unsigned long Q3Memory_CountLiveObjects(void)
{
    return liveObjectCount();
}

TQ3Status Q3Object_Dispose(TQ3Object object)
{
    return guardStatus(__func__, [&] { lookupObject(object, "object").dispose(); });
}

TQ3Object Q3Object_Duplicate(TQ3Object object)
{
    return guard(__func__, TQ3Object{nullptr},
                 [&]() -> TQ3Object { return lookupObject(object, "object").clone(); });
}

TQ3Status Q3Object_Submit(TQ3Object object, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const Object& shape = lookupObject(object, "object");
        lookup<View>(view, "view").submit(shape);
    });
}

TQ3Boolean Q3Object_IsDrawable(TQ3Object object)
{
    return guard(__func__, kQ3False, [&] {
        return lookupObject(object, "object").isDrawable() ? kQ3True : kQ3False;
    });
}

TQ3Boolean Q3Object_IsWritable(TQ3Object object, TQ3FileObject theFile)
{
    return guard(__func__, kQ3False, [&] {
        const Object& source = lookupObject(object, "object");
        lookup<File>(theFile, "theFile");
        return io::classOfObject(source) != nullptr ? kQ3True : kQ3False;
    });
}

TQ3ObjectType Q3Object_GetType(TQ3Object object)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookupObject(object, "object").classInfo().typeAtLevel(1); });
}

TQ3ObjectType Q3Object_GetLeafType(TQ3Object object)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookupObject(object, "object").leafType(); });
}

TQ3Boolean Q3Object_IsType(TQ3Object object, TQ3ObjectType theType)
{
    return guard(__func__, kQ3False,
                 [&] { return lookupObject(object, "object").isType(theType) ? kQ3True : kQ3False; });
}

TQ3ObjectType Q3Shared_GetType(TQ3SharedObject sharedObject)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid}, [&] {
        return lookup<SharedObject>(sharedObject, "sharedObject").classInfo().typeAtLevel(2);
    });
}

TQ3SharedObject Q3Shared_GetReference(TQ3SharedObject sharedObject)
{
    return guard(__func__, TQ3SharedObject{nullptr}, [&]() -> TQ3SharedObject {
        return lookupRef<SharedObject>(sharedObject, "sharedObject").detach();
    });
}

TQ3Boolean Q3Shared_IsReferenced(TQ3SharedObject sharedObject)
{
    return guard(__func__, kQ3False, [&] {
        return lookup<SharedObject>(sharedObject, "sharedObject").referenceCount() > 1 ? kQ3True
                                                                                        : kQ3False;
    });
}

unsigned long Q3Shared_GetEditIndex(TQ3SharedObject sharedObject)
{
    return guard(__func__, 0UL,
                 [&] { return lookup<SharedObject>(sharedObject, "sharedObject").editIndex(); });
}

TQ3Status Q3Shared_Edited(TQ3SharedObject sharedObject)
{
    return guardStatus(__func__,
                       [&] { lookup<SharedObject>(sharedObject, "sharedObject").markEdited(); });
}

TQ3Status Q3Shared_ClearEditTracking(TQ3SharedObject sharedObject)
{
    return guardStatus(__func__,
                       [&] { lookup<SharedObject>(sharedObject, "sharedObject").clearEditTracking(); });
}

TQ3Boolean Q3Shared_GetEditTrackingState(TQ3SharedObject sharedObject)
{
    return guard(__func__, kQ3False, [&] {
        return lookup<SharedObject>(sharedObject, "sharedObject").editedSinceTracking() ? kQ3True : kQ3False;
    });
}

TQ3ObjectType Q3Shape_GetType(TQ3ShapeObject shape)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid}, [&] {
        Object& object = lookupObject(shape, "shape");
        if (!object.isType(kQ3SharedTypeShape))
            fail(kQ3ErrorInvalidObjectType, std::string("shape is a ") + object.classInfo().name);
        return object.classInfo().typeAtLevel(3);
    });
}

} // extern "C"

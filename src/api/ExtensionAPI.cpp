// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DExtension.h: the classes applications register (core/CustomClass.h)
// and their objects (core/CustomObject.h); posting errors from extensions.
#include "QD3DExtension.h"
#include "QD3DIO.h"
#include "api/Entry.h"
#include "core/CustomClass.h"
#include "core/CustomObject.h"
#include "core/EnumValue.h"
#include "io/ClassIO.h"
#include "io/CustomIO.h"
#include "view/View.h"

#include <mutex>
#include <set>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

// The parents an object class may have: those Q3 can make an object of
// without methods of its own (TQ3Object, a shared object, a shape, a group
// class), and the object classes registered under them.
void requireObjectParent(TQ3ObjectType parentType)
{
    if (acceptsCustomSubclasses(parentType))
        return;
    fail(kQ3ErrorInvalidObjectClass,
         "parentType " + std::to_string(parentType) +
             " is no class Q3 registers objects under (0, kQ3ObjectTypeShared, kQ3SharedTypeShape, a group class "
             "or a registered object class)");
}

struct Libraries {
    std::mutex mutex;
    std::set<unsigned long> registered;
};

Libraries& libraries()
{
    static auto* instance = new Libraries;
    return *instance;
}

bool inRange(long code, long first, long last)
{
    return code >= first && code <= last;
}

} // namespace

extern "C" {

TQ3XObjectClass Q3XObjectHierarchy_RegisterClass(TQ3ObjectType parentType, TQ3ObjectType* objectType,
                                                 char* objectName, TQ3XMetaHandler metaHandler,
                                                 TQ3XMetaHandler virtualMetaHandler, unsigned long,
                                                 unsigned long instanceSize)
{
    return guard(__func__, TQ3XObjectClass{nullptr}, [&]() -> TQ3XObjectClass {
        requireNonNull(objectType, "objectType");
        requireNonNull(objectName, "objectName");
        requireObjectParent(parentType);
        if (io::typeOfName(objectName) != 0)
            fail(kQ3ErrorInvalidParameter, std::string("a class named \"") + objectName + "\" is registered already");
        std::shared_ptr<CustomClass> made =
            registerCustomClass(CustomClass::Kind::kObject, kQ3ObjectTypeInvalid, parentType, objectName,
                                instanceSize, metaHandler, virtualMetaHandler);
        if (auto registered = made->methodAs<TQ3XObjectClassRegisterMethod>(kQ3XMethodTypeObjectClassRegister))
            if (registered(made->handle(), nullptr) != kQ3Success) {
                unregisterCustomClass(made->handle());
                fail(kQ3ErrorInvalidParameter, std::string("the register method of \"") + objectName + "\" failed");
            }
        *objectType = made->type();
        return made->handle();
    });
}

TQ3Status Q3XObjectHierarchy_UnregisterClass(TQ3XObjectClass objectClass)
{
    return guardStatus(__func__, [&] { unregisterCustomClass(objectClass); });
}

TQ3XFunctionPointer Q3XObjectClass_GetMethod(TQ3XObjectClass objectClass, TQ3XMethodType methodType)
{
    return guard(__func__, TQ3XFunctionPointer{nullptr},
                 [&] { return lookupCustomClass(objectClass, "objectClass")->method(methodType); });
}

TQ3Object Q3XObjectHierarchy_NewObject(TQ3XObjectClass objectClass, void* parameters)
{
    return guard(__func__, TQ3Object{nullptr}, [&]() -> TQ3Object {
        return CustomInstance::make(lookupCustomClass(objectClass, "objectClass"), parameters);
    });
}

TQ3ObjectType Q3XObjectClass_GetLeafType(TQ3XObjectClass objectClass)
{
    return guard(__func__, TQ3ObjectType{kQ3ObjectTypeInvalid},
                 [&] { return lookupCustomClass(objectClass, "objectClass")->type(); });
}

TQ3Status Q3XObjectHierarchy_GetClassVersion(TQ3ObjectType objectClassType, TQ3XObjectClassVersion* version)
{
    return guardStatus(__func__, [&] {
        if (objectClassType == kQ3ObjectTypeInvalid || findClass(objectClassType) == nullptr)
            fail(kQ3ErrorInvalidParameter,
                 "objectClassType " + std::to_string(objectClassType) + " is not a registered class");
        requireNonNull(version, "version");
        const std::shared_ptr<CustomClass> custom = findCustomClass(objectClassType);
        *version = custom ? custom->version() : Q3_OBJECT_CLASS_VERSION(1, 6);
    });
}

TQ3Status Q3XObjectClass_GetType(TQ3XObjectClass objectClass, TQ3ObjectType* theType)
{
    return guardStatus(__func__, [&] {
        const std::shared_ptr<CustomClass> custom = lookupCustomClass(objectClass, "objectClass");
        requireNonNull(theType, "theType");
        *theType = custom->type();
    });
}

TQ3XObjectClass Q3XObjectHierarchy_FindClassByType(TQ3ObjectType theType)
{
    return guard(__func__, TQ3XObjectClass{nullptr}, [&]() -> TQ3XObjectClass {
        const std::shared_ptr<CustomClass> custom = findCustomClass(theType);
        return custom ? custom->handle() : nullptr;
    });
}

void* Q3XObjectClass_GetPrivate(TQ3XObjectClass objectClass, TQ3Object targetObject)
{
    return guard(__func__, static_cast<void*>(nullptr), [&]() -> void* {
        const std::shared_ptr<CustomClass> custom = lookupCustomClass(objectClass, "objectClass");
        Object& object = lookupObject(targetObject, "targetObject");
        CustomInstance* instance = customInstanceOf(object);
        if (instance == nullptr)
            fail(kQ3ErrorInvalidObjectType, std::string("targetObject is a ") + object.classInfo().name +
                                                ", not of the class \"" + custom->name() + "\"");
        return instance->privateData(*custom);
    });
}

TQ3XObjectClass Q3XObject_GetClass(TQ3Object object)
{
    return guard(__func__, TQ3XObjectClass{nullptr}, [&]() -> TQ3XObjectClass {
        CustomInstance* instance = customInstanceOf(lookupObject(object, "object"));
        if (instance == nullptr)
            return nullptr;
        return findCustomClass(instance->customClass().type())->handle();
    });
}

TQ3Status Q3XSharedLibrary_Register(TQ3XSharedLibraryInfo* sharedLibraryInfo)
{
    return guardStatus(__func__, [&] {
        requireNonNull(sharedLibraryInfo, "sharedLibraryInfo");
        requireNonNull(reinterpret_cast<void*>(sharedLibraryInfo->registerFunction),
                       "sharedLibraryInfo->registerFunction");
        Libraries& all = libraries();
        {
            std::lock_guard<std::mutex> lock(all.mutex);
            if (all.registered.count(sharedLibraryInfo->sharedLibrary) != 0)
                fail(kQ3ErrorInvalidParameter, "the shared library " +
                                                   std::to_string(sharedLibraryInfo->sharedLibrary) +
                                                   " is registered already");
        }
        if (sharedLibraryInfo->registerFunction() != kQ3Success)
            fail(kQ3ErrorInvalidParameter, "the shared library's registration function failed");
        std::lock_guard<std::mutex> lock(all.mutex);
        all.registered.insert(sharedLibraryInfo->sharedLibrary);
    });
}

TQ3Status Q3XSharedLibrary_Unregister(unsigned long sharedLibrary)
{
    return guardStatus(__func__, [&] {
        Libraries& all = libraries();
        std::lock_guard<std::mutex> lock(all.mutex);
        if (all.registered.erase(sharedLibrary) == 0)
            fail(kQ3ErrorInvalidParameter,
                 "the shared library " + std::to_string(sharedLibrary) + " is not registered");
    });
}

// Q3XView_SubmitWriteData and Q3XView_SubmitSubObjectData: deleteData is
// called on failure too, since the caller gave the data away.
TQ3Status Q3XView_SubmitWriteData(TQ3ViewObject view, TQ3Size size, void* data, TQ3XDataDeleteMethod deleteData)
{
    const TQ3Status status = guardStatus(__func__, [&] {
        lookup<View>(view, "view");
        io::activeCustomWrite(view).submitData(size, data, deleteData);
        deleteData = nullptr; // the collector deletes it now
    });
    if (deleteData != nullptr)
        deleteData(data);
    return status;
}

TQ3Status Q3XView_SubmitSubObjectData(TQ3ViewObject view, TQ3XObjectClass objectClass, unsigned long size,
                                      void* data, TQ3XDataDeleteMethod deleteData)
{
    const TQ3Status status = guardStatus(__func__, [&] {
        lookup<View>(view, "view");
        std::shared_ptr<CustomClass> subClass = lookupCustomClass(objectClass, "objectClass");
        io::activeCustomWrite(view).submitSubObjectData(std::move(subClass), size, data, deleteData);
        deleteData = nullptr;
    });
    if (deleteData != nullptr)
        deleteData(data);
    return status;
}

// Posted into the running call (no beginCall): an extension's method posts
// for the call that runs it.
void Q3XError_Post(TQ3Error error)
{
    const long code = enumValue(error);
    if (!inRange(code, kQ3ErrorInternalError, kQ3ErrorInternalError + 199)) {
        errors::postError(kQ3ErrorInvalidParameter,
                          "Q3XError_Post: " + std::to_string(code) + " is no QuickDraw 3D error code");
        return;
    }
    errors::postError(error, "posted by an extension");
}

void Q3XWarning_Post(TQ3Warning warning)
{
    const long code = enumValue(warning);
    if (code == kQ3WarningNone)
        return;
    if (!inRange(code, kQ3WarningInternalException, kQ3WarningInternalException + 199)) {
        errors::postError(kQ3ErrorInvalidParameter,
                          "Q3XWarning_Post: " + std::to_string(code) + " is no QuickDraw 3D warning code");
        return;
    }
    errors::postWarning(warning, "posted by an extension");
}

void Q3XNotice_Post(TQ3Notice notice)
{
    const long code = enumValue(notice);
    if (code == kQ3NoticeNone)
        return;
    if (!inRange(code, kQ3NoticeDataAlreadyEmpty, kQ3NoticeDataAlreadyEmpty + 99)) {
        errors::postError(kQ3ErrorInvalidParameter,
                          "Q3XNotice_Post: " + std::to_string(code) + " is no QuickDraw 3D notice code");
        return;
    }
    errors::postNotice(notice, "posted by an extension");
}

} // extern "C"

// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on the rest of the portable API issue 27
// added: the object-hierarchy queries, the quaternion and rotate-about
// transforms, the view's idle, progress and end-frame methods, renderer
// queries (RAVE contexts: none), edit tracking, the URL element, the shape
// element calls, element and attribute classes, the extension classes'
// queries, posting from extensions, shared libraries, the draw context's
// mask and double-buffer state, unknown binaries' data and type strings, a
// file's idle method, and the release version. Each call keeps the error contract FuzzSession.h checks.

#include "FuzzSession.h"

#include "QD3DAcceleration.h"
#include "QD3DCustomElements.h"

#include <cstdint>
#include <cstring>

namespace q3fuzz {

namespace {

TQ3Status idle(TQ3ViewObject, const void*)
{
    return kQ3Success;
}

TQ3Status idleProgress(TQ3ViewObject, const void*, unsigned long, unsigned long)
{
    return kQ3Success;
}

void endFrame(TQ3ViewObject, void*) {}

TQ3Status fileIdle(TQ3FileObject, const void*)
{
    return kQ3Success;
}

TQ3Status registerLibrary(void)
{
    return kQ3Success;
}

} // namespace

void Session::portable()
{
    const TQ3Object target = pick(static_cast<Kind>(m_in.u8() % kKindCount));
    // A type Q3 defines, or one of the range registered classes take.
    const TQ3ObjectType type = m_in.u8() < 160 ? typeToCount() : TQ3ObjectType(-0x10000 - m_in.u8() % 8);
    switch (m_in.u8() % 16) {
    case 0: {
        TQ3ObjectClassNameString name{};
        if (STATUS(Q3ObjectHierarchy_GetStringFromType(type, name)) == kQ3Success) {
            TQ3ObjectType back = 0;
            STATUS(Q3ObjectHierarchy_GetTypeFromString(name, &back));
            require(QUERY(Q3ObjectHierarchy_IsNameRegistered(name), kQ3False) == kQ3True,
                    "Q3ObjectHierarchy_IsNameRegistered", "the name of a registered type is not registered");
        }
        QUERY(Q3ObjectHierarchy_IsTypeRegistered(type), kQ3False);
        TQ3SubClassData sub{};
        if (STATUS(Q3ObjectHierarchy_GetSubClassData(type, m_in.u8() == 0 ? nullptr : &sub)) == kQ3Success)
            STATUS(Q3ObjectHierarchy_EmptySubClassData(&sub));
        break;
    }
    case 1: {
        const TQ3Quaternion q{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        const std::uint8_t call = m_in.u8() % 4;
        if (call == 0) {
            if (const TQ3Object made = OBJECT(Q3QuaternionTransform_New(m_in.u8() == 0 ? nullptr : &q)))
                hold(made, Kind::kTransform);
        } else if (call == 1) {
            STATUS(Q3QuaternionTransform_Set(target, &q));
        } else if (call == 2) {
            TQ3Quaternion got{};
            STATUS(Q3QuaternionTransform_Get(target, &got));
        } else {
            STATUS(Q3QuaternionTransform_Submit(&q, pick(Kind::kView)));
        }
        break;
    }
    case 2: {
        TQ3RotateAboutPointTransformData d{};
        d.axis = static_cast<TQ3Axis>(m_in.u8() % 3);
        d.radians = m_in.value();
        d.about = point3();
        TQ3RotateAboutPointTransformData got{};
        TQ3Point3D point{};
        float radians = 0;
        TQ3Axis axis = kQ3AxisX;
        switch (m_in.u8() % 9) {
        case 0:
            if (const TQ3Object made = OBJECT(Q3RotateAboutPointTransform_New(&d)))
                hold(made, Kind::kTransform);
            break;
        case 1: STATUS(Q3RotateAboutPointTransform_SetData(target, &d)); break;
        case 2: STATUS(Q3RotateAboutPointTransform_GetData(target, &got)); break;
        case 3: STATUS(Q3RotateAboutPointTransform_SetAxis(target, d.axis)); break;
        case 4: STATUS(Q3RotateAboutPointTransform_GetAxis(target, &axis)); break;
        case 5: STATUS(Q3RotateAboutPointTransform_SetAngle(target, d.radians)); break;
        case 6: STATUS(Q3RotateAboutPointTransform_GetAngle(target, &radians)); break;
        case 7: STATUS(Q3RotateAboutPointTransform_SetAboutPoint(target, &d.about)); break;
        default:
            if (m_in.u8() & 1)
                STATUS(Q3RotateAboutPointTransform_GetAboutPoint(target, &point));
            else
                STATUS(Q3RotateAboutPointTransform_Submit(&d, pick(Kind::kView)));
            break;
        }
        break;
    }
    case 3: {
        TQ3RotateAboutAxisTransformData d{};
        d.origin = point3();
        d.orientation = TQ3Vector3D{m_in.value(), m_in.value(), m_in.value()};
        d.radians = m_in.value();
        TQ3RotateAboutAxisTransformData got{};
        TQ3Point3D point{};
        TQ3Vector3D vector{};
        float radians = 0;
        switch (m_in.u8() % 9) {
        case 0:
            if (const TQ3Object made = OBJECT(Q3RotateAboutAxisTransform_New(&d)))
                hold(made, Kind::kTransform);
            break;
        case 1: STATUS(Q3RotateAboutAxisTransform_SetData(target, &d)); break;
        case 2: STATUS(Q3RotateAboutAxisTransform_GetData(target, &got)); break;
        case 3: STATUS(Q3RotateAboutAxisTransform_SetOrientation(target, &d.orientation)); break;
        case 4: STATUS(Q3RotateAboutAxisTransform_GetOrientation(target, &vector)); break;
        case 5: STATUS(Q3RotateAboutAxisTransform_SetAngle(target, d.radians)); break;
        case 6: STATUS(Q3RotateAboutAxisTransform_GetAngle(target, &radians)); break;
        case 7: STATUS(Q3RotateAboutAxisTransform_SetOrigin(target, &d.origin)); break;
        default:
            if (m_in.u8() & 1)
                STATUS(Q3RotateAboutAxisTransform_GetOrigin(target, &point));
            else
                STATUS(Q3RotateAboutAxisTransform_Submit(&d, pick(Kind::kView)));
            break;
        }
        break;
    }
    case 4: {
        // Methods that never cancel, so the drawing oracles stay as they are.
        const TQ3Object view = pick(Kind::kView);
        const bool clear = m_in.u8() & 1;
        switch (m_in.u8() % 5) {
        case 0: STATUS(Q3View_SetIdleMethod(view, clear ? nullptr : idle, nullptr)); break;
        case 1: STATUS(Q3View_SetIdleProgressMethod(view, clear ? nullptr : idleProgress, nullptr)); break;
        case 2: STATUS(Q3View_SetEndFrameMethod(view, clear ? nullptr : endFrame, nullptr)); break;
        case 3: STATUS(Q3XView_IdleProgress(view, m_in.u32(), m_in.u32())); break;
        default: STATUS(Q3XView_EndFrame(view)); break;
        }
        break;
    }
    case 5: {
        const TQ3Object renderer = pick(Kind::kRenderer);
        QUERY(Q3Renderer_IsInteractive(renderer), kQ3False);
        TQ3ObjectClassNameString nick{};
        STATUS(Q3RendererClass_GetNickNameString(type, nick));
        unsigned long count = 1;
        if (STATUS(Q3InteractiveRenderer_CountRAVEDrawContexts(renderer, &count)) == kQ3Success)
            require(count == 0, "Q3InteractiveRenderer_CountRAVEDrawContexts", "Q3 has no RAVE draw contexts");
        unsigned long hints = 0;
        STATUS(Q3InteractiveRenderer_GetRAVEContextHints(renderer, m_in.u8() == 0 ? nullptr : &hints));
        TQADrawContext* contexts[4] = {};
        TQAEngine* engines[4] = {};
        unsigned long listed = 1;
        if (STATUS(Q3InteractiveRenderer_GetRAVEDrawContexts(renderer, contexts, engines, &listed, nullptr)) ==
            kQ3Success)
            require(listed == 0, "Q3InteractiveRenderer_GetRAVEDrawContexts", "Q3 has no RAVE draw contexts");
        break;
    }
    case 6:
        QUERY(Q3Shared_GetEditTrackingState(target), kQ3False);
        STATUS(Q3Shared_ClearEditTracking(target));
        break;
    case 7: {
        char url[16];
        char description[16];
        for (char& c : url)
            c = static_cast<char>(1 + m_in.u8() % 127);
        url[m_in.u8() % sizeof url] = '\0';
        url[sizeof url - 1] = '\0';
        std::strcpy(description, "described");
        TCEUrlData data{};
        data.url = m_in.u8() == 0 ? nullptr : url;
        data.description = (m_in.u8() & 1) ? description : nullptr;
        setRaw(data.options, std::int32_t(m_in.u8() % 3));
        STATUS(CEUrlElement_SetData(target, m_in.u8() == 0 ? nullptr : &data));
        TCEUrlData* got = nullptr;
        if (STATUS(CEUrlElement_GetData(target, &got)) == kQ3Success && got != nullptr)
            STATUS(CEUrlElement_EmptyData(&got));
        break;
    }
    case 8: {
        const std::uint8_t which = m_in.u8();
        const TQ3ElementType element = which < 200 ? TQ3ElementType(which % 40) : TQ3ElementType(std::int32_t(m_in.u32()));
        QUERY(Q3Object_ContainsElement(target, element), kQ3False);
        switch (m_in.u8() % 6) {
        case 4: {
            // Large enough for any element's C type; a handle is released.
            float out[8] = {};
            if (STATUS(Q3Shape_GetElement(target, element, out)) == kQ3Success &&
                (element == kQ3AttributeTypeSurfaceShader || element == kQ3ElementTypeSet)) {
                TQ3Object got;
                std::memcpy(&got, out, sizeof got);
                Q3Object_Dispose(got);
            }
            break;
        }
        case 5: QUERY(Q3XAttributeSet_GetMask(target), TQ3XAttributeMask{0}); break;
        case 0: STATUS(Q3Object_ClearElement(target, element)); break;
        case 1: {
            TQ3ElementType next = element;
            STATUS(Q3Shape_GetNextElementType(target, &next));
            break;
        }
        case 2: {
            TQ3SetObject set = nullptr;
            if (STATUS(Q3Shape_GetSet(target, &set)) == kQ3Success && set != nullptr)
                STATUS(Q3Object_Dispose(set));
            break;
        }
        default: STATUS(Q3Shape_SetSet(target, (m_in.u8() & 1) ? nullptr : pick(Kind::kAttributeSet))); break;
        }
        break;
    }
    case 9: {
        // A class made, asked about and gone again within the operation.
        const unsigned long size = m_in.u8() < 250 ? m_in.u8() : m_in.u32();
        const bool attribute = m_in.u8() & 1;
        TQ3ElementType registeredType = 0;
        const TQ3XObjectClass made =
            attribute ? POINTER(Q3XAttributeClass_Register(&registeredType, "Fuzz:Attribute", size, nullptr))
                      : POINTER(Q3XElementClass_Register(&registeredType, "Fuzz:Element", size, nullptr));
        require(made == nullptr || m_initialized != 0, "Q3XElementClass_Register", "registered before Q3Initialize");
        if (made == nullptr)
            break;
        unsigned long got = 0;
        if (STATUS(Q3XElementType_GetElementSize(registeredType, &got)) == kQ3Success)
            require(got == size, "Q3XElementType_GetElementSize", "not the size the class was registered with");
        STATUS(Q3XObjectHierarchy_UnregisterClass(made));
        break;
    }
    case 10: {
        const TQ3XObjectClass found = QUERY(Q3XObjectHierarchy_FindClassByType(type), TQ3XObjectClass{nullptr});
        QUERY(Q3XObjectClass_GetLeafType(found), TQ3ObjectType{kQ3ObjectTypeInvalid});
        TQ3ObjectType got = 0;
        STATUS(Q3XObjectClass_GetType(found, &got));
        QUERY(Q3XObjectClass_GetMethod(found, m_in.u32()), TQ3XFunctionPointer{nullptr});
        QUERY(Q3XObjectClass_GetPrivate(found, target), static_cast<void*>(nullptr));
        QUERY(Q3XObject_GetClass(target), TQ3XObjectClass{nullptr});
        TQ3XObjectClassVersion version = 0;
        STATUS(Q3XObjectHierarchy_GetClassVersion(type, &version));
        break;
    }
    case 11: {
        // They post what they are given (or, for a code that is none,
        // kQ3ErrorInvalidParameter) into the running call: none here.
        const std::int32_t code = std::int32_t(m_in.u32());
        begin();
        switch (m_in.u8() % 3) {
        case 0: q3fuzz_PostError(code); break;
        case 1: q3fuzz_PostWarning(code); break;
        default: q3fuzz_PostNotice(code); break;
        }
        begin();
        break;
    }
    case 12: {
        TQ3XSharedLibraryInfo info{registerLibrary, m_in.u8()};
        if (STATUS(Q3XSharedLibrary_Register(m_in.u8() == 0 ? nullptr : &info)) == kQ3Success || (m_in.u8() & 1))
            STATUS(Q3XSharedLibrary_Unregister(info.sharedLibrary));
        break;
    }
    case 13: {
        const TQ3Object context = pick(Kind::kDrawContext);
        static unsigned char image[512];
        TQ3Bitmap mask{};
        mask.width = m_in.u8() % 17;
        mask.height = m_in.u8() % 17;
        mask.rowBytes = m_in.u8() % 9; // at most 8 * 16 = 128 bytes are read
        mask.image = m_in.u8() == 0 ? nullptr : image;
        setRaw(mask.bitOrder, std::int32_t(m_in.u8() % 3));
        TQ3Boolean state = kQ3False;
        switch (m_in.u8() % 6) {
        case 0: STATUS(Q3DrawContext_SetMask(context, &mask)); break;
        case 1: {
            // The draw context hands back the caller's own bits (its
            // SetMask stores the bitmap as given, as QuickDraw 3D's does):
            // not the caller's to free with Q3Bitmap_Empty.
            TQ3Bitmap got{};
            STATUS(Q3DrawContext_GetMask(context, &got));
            break;
        }
        case 2: STATUS(Q3DrawContext_SetMaskState(context, (m_in.u8() & 1) ? kQ3True : kQ3False)); break;
        case 3: STATUS(Q3DrawContext_GetMaskState(context, &state)); break;
        case 4: STATUS(Q3DrawContext_SetDoubleBufferState(context, (m_in.u8() & 1) ? kQ3True : kQ3False)); break;
        default: STATUS(Q3DrawContext_GetDoubleBufferState(context, &state)); break;
        }
        break;
    }
    case 14: {
        char* typeString = nullptr;
        if (STATUS(Q3UnknownBinary_GetTypeString(target, &typeString)) == kQ3Success)
            STATUS(Q3UnknownBinary_EmptyTypeString(&typeString));
        TQ3UnknownBinaryData data{};
        if (STATUS(Q3UnknownBinary_GetData(target, &data)) == kQ3Success)
            STATUS(Q3UnknownBinary_EmptyData(&data));
        break;
    }
    default: {
        unsigned long release = 0;
        STATUS(Q3GetReleaseVersion(m_in.u8() == 0 ? nullptr : &release));
        QUERY(Q3MemoryStorage_GetType(target), TQ3ObjectType{kQ3ObjectTypeInvalid});
        QUERY(Q3Object_IsWritable(target, nullptr), kQ3False);
        // A file's idle method, set and cleared on a file of its own.
        if (const TQ3Object file = OBJECT(Q3File_New())) {
            STATUS(Q3File_SetIdleMethod(file, (m_in.u8() & 1) ? nullptr : fileIdle, nullptr));
            STATUS(Q3Object_Dispose(file));
        }
        break;
    }
    }
}

} // namespace q3fuzz

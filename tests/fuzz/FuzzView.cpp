// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on cameras, draw contexts, renderers, views, picking, controllers and view hints.

#include "FuzzSession.h"

namespace q3fuzz {

void Session::picking()
{
    const std::uint8_t call = m_in.u8() % 8;
    const bool nullArg = m_in.u8() == 0;
    if (call == 0) {
        TQ3PickData common{};
        setRaw(common.sort, enumValue(3));
        common.mask = m_in.u8() < 200 ? (m_in.u32() & 0x3FF) : m_in.u32();
        common.numHitsToReturn = m_in.u8() % 4;
        TQ3Object made = nullptr;
        switch (m_in.u8() % 3) {
        case 0: {
            TQ3WindowPointPickData d{common, {m_in.value(), m_in.value()}, m_in.value(), m_in.value()};
            made = OBJECT(Q3WindowPointPick_New(nullArg ? nullptr : &d));
            break;
        }
        case 1: {
            TQ3WindowRectPickData d{common, {{m_in.value(), m_in.value()}, {m_in.value(), m_in.value()}}};
            made = OBJECT(Q3WindowRectPick_New(nullArg ? nullptr : &d));
            break;
        }
        default: {
            TQ3WorldRayPickData d{common,
                                  {{m_in.value(), m_in.value(), m_in.value()},
                                   {m_in.value(), m_in.value(), m_in.value()}},
                                  m_in.value(),
                                  m_in.value()};
            made = OBJECT(Q3WorldRayPick_New(nullArg ? nullptr : &d));
            break;
        }
        }
        if (made != nullptr) {
            hold(made, Kind::kPick);
            TQ3PickData got{};
            STATUS(Q3Pick_GetData(made, &got));
            require(got.mask == common.mask && got.numHitsToReturn == common.numHitsToReturn, "Q3Pick_GetData",
                    "differs from what the pick was made with");
        }
        return;
    }
    const TQ3Object pick = this->pick(Kind::kPick);
    switch (call) {
    case 1: {
        TQ3WindowPointPickData point;
        TQ3WindowRectPickData rect;
        TQ3WorldRayPickData ray;
        std::memset(&point, 0xA5, sizeof point);
        std::memset(&rect, 0xA5, sizeof rect);
        std::memset(&ray, 0xA5, sizeof ray);
        const bool gotPoint = STATUS(Q3WindowPointPick_GetData(pick, &point)) == kQ3Success;
        const bool gotRect = STATUS(Q3WindowRectPick_GetData(pick, &rect)) == kQ3Success;
        const bool gotRay = STATUS(Q3WorldRayPick_GetData(pick, &ray)) == kQ3Success;
        const float value = m_in.value();
        TQ3Status status = kQ3Success;
        switch (m_in.u8() % 6) {
        case 0: status = STATUS(Q3Pick_SetVertexTolerance(pick, value)); break;
        case 1: status = STATUS(Q3Pick_SetEdgeTolerance(pick, value)); break;
        case 2: {
            const TQ3Point2D p{value, m_in.value()};
            status = STATUS(Q3WindowPointPick_SetPoint(pick, nullArg ? nullptr : &p));
            break;
        }
        case 3: {
            const TQ3Area a{{value, m_in.value()}, {m_in.value(), m_in.value()}};
            status = STATUS(Q3WindowRectPick_SetRect(pick, nullArg ? nullptr : &a));
            break;
        }
        case 4: {
            const TQ3Ray3D r{{value, m_in.value(), m_in.value()}, {m_in.value(), m_in.value(), m_in.value()}};
            status = STATUS(Q3WorldRayPick_SetRay(pick, nullArg ? nullptr : &r));
            break;
        }
        default: {
            TQ3PickData d{};
            setRaw(d.sort, enumValue(3));
            d.mask = m_in.u8() < 200 ? (m_in.u32() & 0x3FF) : m_in.u32();
            d.numHitsToReturn = m_in.u8() % 4;
            status = STATUS(Q3Pick_SetData(pick, nullArg ? nullptr : &d));
            break;
        }
        }
        if (status != kQ3Success) {
            TQ3WindowPointPickData point2;
            TQ3WindowRectPickData rect2;
            TQ3WorldRayPickData ray2;
            std::memset(&point2, 0xA5, sizeof point2);
            std::memset(&rect2, 0xA5, sizeof rect2);
            std::memset(&ray2, 0xA5, sizeof ray2);
            if (gotPoint && STATUS(Q3WindowPointPick_GetData(pick, &point2)) == kQ3Success)
                require(sameBytes(point, point2), "Q3WindowPointPick_Set*", "failed but changed the pick");
            if (gotRect && STATUS(Q3WindowRectPick_GetData(pick, &rect2)) == kQ3Success)
                require(sameBytes(rect, rect2), "Q3WindowRectPick_Set*", "failed but changed the pick");
            if (gotRay && STATUS(Q3WorldRayPick_GetData(pick, &ray2)) == kQ3Success)
                require(sameBytes(ray, ray2), "Q3WorldRayPick_Set*", "failed but changed the pick");
        }
        return;
    }
    case 2: {
        float tolerance = 0.0f;
        TQ3Point2D point{};
        TQ3Area area{};
        TQ3Ray3D ray{};
        TQ3PickData data{};
        QUERY(Q3Pick_GetType(pick), TQ3ObjectType{kQ3ObjectTypeInvalid});
        STATUS(Q3Pick_GetVertexTolerance(pick, nullArg ? nullptr : &tolerance));
        STATUS(Q3Pick_GetEdgeTolerance(pick, nullArg ? nullptr : &tolerance));
        STATUS(Q3WindowPointPick_GetPoint(pick, nullArg ? nullptr : &point));
        STATUS(Q3WindowRectPick_GetRect(pick, nullArg ? nullptr : &area));
        STATUS(Q3WorldRayPick_GetRay(pick, nullArg ? nullptr : &ray));
        STATUS(Q3Pick_GetData(pick, nullArg ? nullptr : &data));
        return;
    }
    case 3: {
        const TQ3Object view = this->pick(Kind::kView);
        if (m_loops >= kMaxLoops)
            return;
        ++m_loops;
        STATUS(Q3View_StartPicking(view, pick));
        return;
    }
    case 4:
        VIEWSTATUS(Q3View_EndPicking(this->pick(Kind::kView)));
        return;
    case 5: {
        // Every byte is read before the calls, so a failing one leaves
        // the rest of the input decoding as written.
        const std::uint32_t raw = m_in.u32();
        const bool inRange = m_in.u8() < 200;
        const TQ3PickDetail asked = m_in.u8() < 200 ? (1ul << (m_in.u8() % 10)) : m_in.u32();
        unsigned long count = 0;
        TQ3PickData data{};
        if (STATUS(Q3Pick_GetNumHits(pick, &count)) != kQ3Success ||
            STATUS(Q3Pick_GetData(pick, &data)) != kQ3Success)
            return;
        require(data.numHitsToReturn == 0 || count <= data.numHitsToReturn, "Q3Pick_GetNumHits",
                "more hits than numHitsToReturn");
        const unsigned long index = inRange && count != 0 ? raw % count : raw;
        TQ3PickDetail valid = 0;
        if (STATUS(Q3Pick_GetPickDetailValidMask(pick, index, nullArg ? nullptr : &valid)) != kQ3Success)
            return;
        require((valid & ~data.mask) == 0, "Q3Pick_GetPickDetailValidMask",
                "reports a detail the pick did not ask for");
        union {
            unsigned long id;
            TQ3HitPath path;
            TQ3Object object;
            TQ3Matrix4x4 matrix;
            TQ3Point3D xyz;
            float distance;
            TQ3Vector3D normal;
            TQ3PickParts part;
            TQ3Param2D uv;
        } out;
        std::memset(&out, 0, sizeof out);
        if (STATUS(Q3Pick_GetPickDetailData(pick, index, asked, &out)) != kQ3Success)
            return;
        require((valid & asked) == asked, "Q3Pick_GetPickDetailData", "gave a detail that is not valid");
        if (asked == kQ3PickDetailMaskObject)
            STATUS(Q3Object_Dispose(out.object));
        if (asked == kQ3PickDetailMaskShapePart) {
            // A mesh part: every shape part call, the right one succeeding.
            TQ3ShapeObject shape = nullptr;
            if (STATUS(Q3ShapePart_GetShape(out.object, &shape)) == kQ3Success)
                STATUS(Q3Object_Dispose(shape));
            require(QUERY(Q3ShapePart_GetType(out.object), TQ3ObjectType{kQ3ObjectTypeInvalid}) ==
                        kQ3ShapePartTypeMeshPart,
                    "Q3ShapePart_GetType", "a part that is not a mesh part");
            const TQ3ObjectType meshPart = QUERY(Q3MeshPart_GetType(out.object), TQ3ObjectType{kQ3ObjectTypeInvalid});
            require(meshPart == kQ3MeshPartTypeMeshFacePart || meshPart == kQ3MeshPartTypeMeshEdgePart ||
                        meshPart == kQ3MeshPartTypeMeshVertexPart,
                    "Q3MeshPart_GetType", "a mesh part that is no face, edge or vertex part");
            TQ3MeshComponent component = nullptr;
            TQ3MeshFace face = nullptr;
            TQ3MeshEdge edge = nullptr;
            TQ3MeshVertex vertex = nullptr;
            STATUS(Q3MeshPart_GetComponent(out.object, &component));
            STATUS(Q3MeshFacePart_GetFace(out.object, &face));
            STATUS(Q3MeshEdgePart_GetEdge(out.object, &edge));
            STATUS(Q3MeshVertexPart_GetVertex(out.object, &vertex));
            STATUS(Q3Object_Dispose(out.object));
        }
        if (asked == kQ3PickDetailMaskPath) {
            require(out.path.rootGroup != nullptr && out.path.depth != 0, "Q3Pick_GetPickDetailData",
                    "gave an empty path");
            STATUS(Q3HitPath_EmptyData(&out.path));
        }
        return;
    }
    case 6: {
        STATUS(Q3Pick_EmptyHitList(pick));
        TQ3HitPath empty{nullptr, 0, nullptr};
        STATUS(Q3HitPath_EmptyData(nullArg ? nullptr : &empty));
        return;
    }
    default:
        QUERY(Q3Pick_GetType(pick), TQ3ObjectType{kQ3ObjectTypeInvalid});
        return;
    }
}

void Session::controllers()
{
    const std::uint8_t call = m_in.u8() % 14;
    const bool nullArg = m_in.u8() == 0;
    TQ3ControllerRef ref = &m_notAController;
    if (!m_controllers.empty() && m_in.u8() != 0)
        ref = m_controllers[m_in.u8() % m_controllers.size()];
    TQ3TrackerObject tracker = OBJECT(Q3Tracker_New((m_in.u8() & 1) ? fuzzTrackerNotify : nullptr));
    const TQ3Point3D point{m_in.value(), m_in.value(), m_in.value()};
    const TQ3Vector3D vector{m_in.value(), m_in.value(), m_in.value()};
    const TQ3Quaternion turn{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
    TQ3Boolean b = kQ3False;
    unsigned long n = m_in.u32();
    switch (call) {
    case 0: {
        char signature[] = "dev?";
        signature[3] = char('a' + m_in.u8() % 4);
        const unsigned long counts[] = {0, 3, 1024, 1025, 0xFFFFFFFFul};
        TQ3ControllerData data{signature, counts[m_in.u8() % 5], counts[m_in.u8() % 5] % 1100, fuzzGetChannel,
                               fuzzSetChannel};
        if (m_in.u8() == 0)
            data.signature = nullptr;
        if (TQ3ControllerRef made = POINTER(Q3Controller_New(nullArg ? nullptr : &data)))
            if (std::find(m_controllers.begin(), m_controllers.end(), made) == m_controllers.end())
                m_controllers.push_back(made);
        break;
    }
    case 1: {
        TQ3ControllerRef next = nullptr;
        STATUS(Q3Controller_GetListChanged(nullArg ? nullptr : &b, &n));
        const bool fromStart = m_in.u8() & 1;
        STATUS(Q3Controller_Next(fromStart ? nullptr : ref, nullArg ? nullptr : &next));
        STATUS(Q3Controller_GetActivation(ref, nullArg ? nullptr : &b));
        STATUS(Q3Controller_GetValueCount(ref, nullArg ? nullptr : &n));
        STATUS(Q3Controller_HasTracker(ref, nullArg ? nullptr : &b));
        STATUS(Q3Controller_Track2DCursor(ref, nullArg ? nullptr : &b));
        STATUS(Q3Controller_Track3DCursor(ref, nullArg ? nullptr : &b));
        STATUS(Q3Controller_GetButtons(ref, nullArg ? nullptr : &n));
        break;
    }
    case 2:
        STATUS(Q3Controller_SetActivation(ref, static_cast<TQ3Boolean>(m_in.u8() % 3)));
        if (m_in.u8() % 8 == 0)
            STATUS(Q3Controller_Decommission(ref));
        break;
    case 3: {
        char text[16];
        const unsigned long numChars = m_in.u8() % 17;
        STATUS(Q3Controller_GetSignature(ref, nullArg ? nullptr : text, numChars));
        unsigned char bytes[300] = {};
        unsigned long size = m_in.u32() % 300;
        const unsigned long setChannel = m_in.u8() % 6;
        const unsigned long getChannel = m_in.u8() % 6;
        STATUS(Q3Controller_SetChannel(ref, setChannel, nullArg ? nullptr : bytes, size));
        STATUS(Q3Controller_GetChannel(ref, getChannel, nullArg ? nullptr : bytes, &size));
        break;
    }
    case 4: {
        const bool toCursor = m_in.u8() & 1;
        STATUS(Q3Controller_SetTracker(ref, toCursor ? nullptr : tracker));
        const unsigned long buttons = m_in.u32();
        STATUS(Q3Controller_SetButtons(ref, buttons));
        break;
    }
    case 5: {
        TQ3Point3D p{};
        TQ3Quaternion q{};
        STATUS(Q3Controller_SetTrackerPosition(ref, nullArg ? nullptr : &point));
        STATUS(Q3Controller_MoveTrackerPosition(ref, &vector));
        STATUS(Q3Controller_SetTrackerOrientation(ref, &turn));
        STATUS(Q3Controller_MoveTrackerOrientation(ref, &turn));
        STATUS(Q3Controller_GetTrackerPosition(ref, nullArg ? nullptr : &p));
        STATUS(Q3Controller_GetTrackerOrientation(ref, nullArg ? nullptr : &q));
        break;
    }
    case 6: {
        float values[8] = {m_in.value(), m_in.value(), m_in.value()};
        const unsigned long setCount = m_in.u8() % 9;
        STATUS(Q3Controller_SetValues(ref, nullArg ? nullptr : values, setCount));
        unsigned long serial = m_in.u8();
        const unsigned long getCount = m_in.u8() % 9;
        const bool noSerial = m_in.u8() & 1;
        STATUS(Q3Controller_GetValues(ref, getCount, values, nullArg ? nullptr : &b, noSerial ? nullptr : &serial));
        break;
    }
    case 7: {
        const TQ3Object state = OBJECT(Q3ControllerState_New(ref));
        STATUS(Q3ControllerState_Restore(state));
        STATUS(Q3ControllerState_SaveAndReset(nullArg ? tracker : state));
        STATUS(Q3ControllerState_Restore(state));
        if (state != nullptr)
            STATUS(Q3Object_Dispose(state));
        break;
    }
    case 8: {
        float p = 0, o = 0;
        const float positionThresh = m_in.value();
        const float orientationThresh = m_in.value();
        STATUS(Q3Tracker_SetNotifyThresholds(tracker, positionThresh, orientationThresh));
        STATUS(Q3Tracker_GetNotifyThresholds(tracker, nullArg ? nullptr : &p, &o));
        STATUS(Q3Tracker_SetActivation(tracker, static_cast<TQ3Boolean>(m_in.u8() % 3)));
        STATUS(Q3Tracker_GetActivation(tracker, nullArg ? nullptr : &b));
        const bool byApplication = m_in.u8() & 1;
        const unsigned long buttons = m_in.u32();
        const unsigned long mask = m_in.u32();
        STATUS(Q3Tracker_ChangeButtons(tracker, byApplication ? nullptr : ref, buttons, mask));
        STATUS(Q3Tracker_GetButtons(tracker, nullArg ? nullptr : &n));
        break;
    }
    case 9: {
        const TQ3ControllerRef by = m_in.u8() & 1 ? nullptr : ref;
        TQ3Point3D p{};
        TQ3Vector3D d{};
        TQ3Quaternion q{}, dq{};
        unsigned long serial = m_in.u8();
        STATUS(Q3Tracker_SetPosition(tracker, by, nullArg ? nullptr : &point));
        STATUS(Q3Tracker_MovePosition(tracker, by, &vector));
        STATUS(Q3Tracker_SetOrientation(tracker, by, &turn));
        STATUS(Q3Tracker_MoveOrientation(tracker, by, &turn));
        const std::uint8_t outs = m_in.u8();
        STATUS(Q3Tracker_GetPosition(tracker, nullArg ? nullptr : &p, outs & 1 ? nullptr : &d, &b,
                                     outs & 2 ? nullptr : &serial));
        STATUS(Q3Tracker_GetOrientation(tracker, &q, outs & 4 ? nullptr : &dq, nullArg ? nullptr : &b,
                                        outs & 8 ? nullptr : &serial));
        break;
    }
    case 10: {
        const std::uint8_t events = m_in.u8() % 20;
        for (std::uint8_t i = 0; i < events; ++i) {
            const unsigned long time = m_in.u32();
            const unsigned long buttons = m_in.u32();
            const std::uint8_t given = m_in.u8();
            STATUS(Q3Tracker_SetEventCoordinates(tracker, time, buttons, given & 1 ? nullptr : &point,
                                                 given & 2 ? nullptr : &turn));
        }
        TQ3Point3D p{};
        TQ3Quaternion q{};
        const unsigned long time = m_in.u32();
        STATUS(Q3Tracker_GetEventCoordinates(tracker, time, nullArg ? nullptr : &n, &p, &q));
        break;
    }
    case 11: {
        float depth = 0;
        TQ3Quaternion q{};
        TQ3Boolean has = kQ3False;
        unsigned long serial = m_in.u8();
        STATUS(Q3CursorTracker_PrepareTracking());
        STATUS(Q3CursorTracker_SetTrackDeltas(static_cast<TQ3Boolean>(m_in.u8() % 3)));
        const bool noSerial = m_in.u8() & 1;
        STATUS(Q3CursorTracker_GetAndClearDeltas(nullArg ? nullptr : &depth, &q, &has, &b,
                                                 noSerial ? nullptr : &serial));
        break;
    }
    case 12: {
        TQ3CursorTrackerNotifyFunc f = nullptr;
        STATUS(Q3CursorTracker_SetNotifyFunc(m_in.u8() & 1 ? fuzzCursorNotify : nullptr));
        STATUS(Q3CursorTracker_GetNotifyFunc(nullArg ? nullptr : &f));
        break;
    }
    default:
        // The same calls on a tracker handle that is something else.
        STATUS(Q3Tracker_GetButtons(pick(Kind::kView), &n));
        STATUS(Q3Controller_SetTracker(ref, pick(Kind::kAttributeSet)));
        break;
    }
    if (tracker != nullptr)
        STATUS(Q3Object_Dispose(tracker));
}

void Session::viewHints()
{
    const std::uint8_t call = m_in.u8() % 12;
    if (call == 0) {
        const TQ3Object hints = OBJECT(Q3ViewHints_New(pick(Kind::kView)));
        if (hints != nullptr)
            hold(hints, Kind::kViewHints);
        return;
    }
    const TQ3Object hints = pick(Kind::kViewHints);
    const bool ours = holdsKind(hints, Kind::kViewHints) && m_initialized > 0;
    const bool nullArg = m_in.u8() == 0;
    const unsigned long before = ours ? editIndex(hints) : 0;
    TQ3Status status = kQ3Success;
    bool edit = true;
    switch (call) {
    case 1: status = STATUS(Q3ViewHints_SetCamera(hints, pick(Kind::kCamera))); break;
    case 2: status = STATUS(Q3ViewHints_SetRenderer(hints, pick(Kind::kRenderer))); break;
    case 3: status = STATUS(Q3ViewHints_SetLightGroup(hints, pick(Kind::kGroup))); break;
    case 4: status = STATUS(Q3ViewHints_SetAttributeSet(hints, pick(Kind::kAttributeSet))); break;
    case 5: {
        edit = false;
        TQ3Object got[4] = {};
        STATUS(Q3ViewHints_GetCamera(hints, nullArg ? nullptr : &got[0]));
        STATUS(Q3ViewHints_GetRenderer(hints, nullArg ? nullptr : &got[1]));
        STATUS(Q3ViewHints_GetLightGroup(hints, nullArg ? nullptr : &got[2]));
        STATUS(Q3ViewHints_GetAttributeSet(hints, nullArg ? nullptr : &got[3]));
        for (TQ3Object object : got)
            if (object != nullptr)
                STATUS(Q3Object_Dispose(object));
        break;
    }
    case 6: {
        // Widths past 32 bits where unsigned long has them.
        const std::uint8_t shift = m_in.u8() % 40;
        const unsigned long width = static_cast<unsigned long>(std::uint64_t{m_in.u32()} << (shift % 33));
        status = STATUS(Q3ViewHints_SetDimensions(hints, width, m_in.u32()));
        break;
    }
    case 7:
        status = STATUS(Q3ViewHints_SetDimensionsState(hints, (m_in.u8() & 1) ? kQ3True : kQ3False));
        if (status == kQ3Success)
            status = STATUS(Q3ViewHints_SetMaskState(hints, (m_in.u8() & 1) ? kQ3True : kQ3False));
        break;
    case 8: {
        edit = false;
        TQ3Boolean state = kQ3False;
        unsigned long width = 0, height = 0;
        STATUS(Q3ViewHints_GetDimensionsState(hints, nullArg ? nullptr : &state));
        STATUS(Q3ViewHints_GetMaskState(hints, nullArg ? nullptr : &state));
        STATUS(Q3ViewHints_GetDimensions(hints, nullArg ? nullptr : &width, &height));
        TQ3Bitmap mask;
        std::memset(&mask, 0xA5, sizeof mask);
        const TQ3Bitmap untouched = mask;
        if (STATUS(Q3ViewHints_GetMask(hints, nullArg ? nullptr : &mask)) == kQ3Success)
            STATUS(Q3Bitmap_Empty(&mask));
        else
            require(sameBytes(mask, untouched), "Q3ViewHints_GetMask", "failed but wrote its output");
        break;
    }
    case 9: {
        // A bitmap whose image holds every byte it claims (or NULL):
        // 0..63 x 0..63 pixels, rows of the bytes the width needs plus
        // 0..2, a bit order from the input.
        const unsigned long width = m_in.u8() % 64, height = m_in.u8() % 64;
        const unsigned long rowBytes = (width + 7) / 8 + m_in.u8() % 3;
        std::vector<unsigned char> image(rowBytes * height + 1, 0x3C);
        TQ3Bitmap mask{nullArg ? nullptr : image.data(), width, height, rowBytes, kQ3EndianBig};
        setRaw(mask.bitOrder, enumValue(1));
        status = STATUS(Q3ViewHints_SetMask(hints, &mask));
        break;
    }
    case 10: {
        status = STATUS(q3fuzz_ViewHints_SetClearImageMethod(hints, enumValue(1)));
        TQ3DrawContextClearImageMethod method;
        STATUS(Q3ViewHints_GetClearImageMethod(hints, nullArg ? nullptr : &method));
        break;
    }
    default: {
        const TQ3ColorARGB color{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        status = STATUS(Q3ViewHints_SetClearImageColor(hints, nullArg ? nullptr : &color));
        TQ3ColorARGB got;
        STATUS(Q3ViewHints_GetClearImageColor(hints, &got));
        break;
    }
    }
    if (ours && edit && status == kQ3Failure)
        require(editIndex(hints) == before, "Q3ViewHints_Set...", "failed but changed the hints");
}

void Session::newCamera()
{
    TQ3Object camera = nullptr;
    const bool nullData = m_in.u8() == 0;
    switch (m_in.u8() % 3) {
    case 0: {
        TQ3OrthographicCameraData data{readCameraData(), -2.0f, 1.5f, 2.0f, -1.5f};
        if (m_in.u8() & 1) {
            data.left = m_in.value();
            data.top = m_in.value();
            data.right = m_in.value();
            data.bottom = m_in.value();
        }
        camera = OBJECT(Q3OrthographicCamera_New(nullData ? nullptr : &data));
        break;
    }
    case 1: {
        TQ3ViewPlaneCameraData data{readCameraData(), 10.0f, 2.0f, 1.5f, 0.0f, 0.0f};
        if (m_in.u8() & 1) {
            data.viewPlane = m_in.value();
            data.halfWidthAtViewPlane = m_in.value();
            data.halfHeightAtViewPlane = m_in.value();
            data.centerXOnViewPlane = m_in.value();
            data.centerYOnViewPlane = m_in.value();
        }
        camera = OBJECT(Q3ViewPlaneCamera_New(nullData ? nullptr : &data));
        break;
    }
    default: {
        TQ3ViewAngleAspectCameraData data{readCameraData(), 0.8f, 1.0f};
        if (m_in.u8() & 1) {
            data.fov = m_in.value();
            data.aspectRatioXToY = m_in.value();
        }
        camera = OBJECT(Q3ViewAngleAspectCamera_New(nullData ? nullptr : &data));
        break;
    }
    }
    if (camera != nullptr)
        hold(camera, Kind::kCamera);
}

void Session::cameraEdit()
{
    const TQ3Object camera = pick(Kind::kCamera);
    const bool nullArg = m_in.u8() == 0;
    TQ3CameraData data = readCameraData();
    TQ3Matrix4x4 matrix;
    switch (m_in.u8() % 10) {
    case 0: STATUS(Q3Camera_SetData(camera, nullArg ? nullptr : &data)); break;
    case 1: STATUS(Q3Camera_GetData(camera, nullArg ? nullptr : &data)); break;
    case 2: STATUS(Q3Camera_SetPlacement(camera, nullArg ? nullptr : &data.placement)); break;
    case 3: STATUS(Q3Camera_SetRange(camera, nullArg ? nullptr : &data.range)); break;
    case 4: STATUS(Q3Camera_SetViewPort(camera, nullArg ? nullptr : &data.viewPort)); break;
    case 5: STATUS(Q3Camera_GetWorldToFrustum(camera, nullArg ? nullptr : &matrix)); break;
    case 6: STATUS(Q3Camera_GetViewToFrustum(camera, nullArg ? nullptr : &matrix)); break;
    case 7: STATUS(Q3Camera_GetWorldToView(camera, nullArg ? nullptr : &matrix)); break;
    case 8: QUERY(Q3Camera_GetType(camera), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
    default: {
        TQ3ViewAngleAspectCameraData angle{data, m_in.value(), m_in.value()};
        STATUS(Q3ViewAngleAspectCamera_SetData(camera, nullArg ? nullptr : &angle));
        break;
    }
    }
}

TQ3Pixmap Session::readPixmap()
{
    TQ3Pixmap pixmap{};
    const std::uint8_t shape = m_in.u8();
    static const unsigned long kSizes[] = {32, 32, 16, 16, 16, 24};
    const std::int32_t type = enumValue(6);
    setRaw(pixmap.pixelType, type);
    const unsigned long bits = type >= 0 && type < 6 ? kSizes[type] : 32;
    pixmap.pixelSize = (shape & 1) ? m_in.u8() : bits;
    if (shape & 2) {
        // A wide strip, up to beyond what the renderer supports.
        pixmap.width = m_in.u16();
        pixmap.height = m_in.u8() % 3;
    } else {
        pixmap.width = m_in.u8() % 70;
        pixmap.height = m_in.u8() % 70;
    }
    pixmap.rowBytes = pixmap.width * ((bits + 7) / 8) + m_in.u8() % 8;
    if (shape & 4)
        pixmap.rowBytes = m_in.u16() % (pixmap.rowBytes + 1);
    setRaw(pixmap.byteOrder, enumValue(2));
    setRaw(pixmap.bitOrder, enumValue(2));
    const std::size_t bytes = std::max<std::size_t>(pixmap.rowBytes, pixmap.width * 4) *
                                  std::max<std::size_t>(pixmap.height, 1) + 8;
    m_images.push_back(std::make_unique<std::vector<unsigned char>>(bytes, 0x5A));
    pixmap.image = (shape & 8) ? nullptr : m_images.back()->data();
    return pixmap;
}

TQ3DrawContextData Session::readDrawContextData()
{
    TQ3DrawContextData data{};
    setRaw(data.clearImageMethod, enumValue(2));
    data.clearImageColor = {m_in.value(), m_in.value(), m_in.value(), m_in.value()};
    data.pane = {{m_in.value(), m_in.value()}, {m_in.value(), m_in.value()}};
    setRaw(data.paneState, enumValue(2));
    setRaw(data.maskState, enumValue(2));
    setRaw(data.doubleBufferState, enumValue(2));
    return data;
}

void Session::newDrawContext()
{
    if (m_drawContexts >= kMaxDrawContexts)
        return;
    ++m_drawContexts;
    TQ3PixmapDrawContextData data{};
    data.drawContextData = readDrawContextData();
    data.pixmap = readPixmap();
    const TQ3Object context = OBJECT(Q3PixmapDrawContext_New(m_in.u8() == 0 ? nullptr : &data));
    if (context != nullptr)
        hold(context, Kind::kDrawContext);
}

void Session::drawContextEdit()
{
    const TQ3Object context = pick(Kind::kDrawContext);
    const bool nullArg = m_in.u8() == 0;
    TQ3DrawContextData data = readDrawContextData();
    switch (m_in.u8() % 12) {
    case 0: STATUS(Q3DrawContext_SetData(context, nullArg ? nullptr : &data)); break;
    case 1: STATUS(Q3DrawContext_GetData(context, nullArg ? nullptr : &data)); break;
    case 2: STATUS(Q3DrawContext_SetClearImageColor(context, nullArg ? nullptr : &data.clearImageColor)); break;
    case 3: STATUS(Q3DrawContext_GetClearImageColor(context, nullArg ? nullptr : &data.clearImageColor)); break;
    case 4: STATUS(Q3DrawContext_SetPane(context, nullArg ? nullptr : &data.pane)); break;
    case 5: STATUS(Q3DrawContext_GetPane(context, nullArg ? nullptr : &data.pane)); break;
    case 6: STATUS(q3fuzz_SetPaneState(context, enumValue(2))); break;
    case 7: STATUS(Q3DrawContext_GetPaneState(context, nullArg ? nullptr : &data.paneState)); break;
    case 8: STATUS(q3fuzz_SetClearImageMethod(context, enumValue(2))); break;
    case 9: STATUS(Q3DrawContext_GetClearImageMethod(context, nullArg ? nullptr : &data.clearImageMethod)); break;
    case 10: {
        if (m_drawContexts >= kMaxDrawContexts)
            break;
        ++m_drawContexts;
        const TQ3Pixmap pixmap = readPixmap();
        STATUS(Q3PixmapDrawContext_SetPixmap(context, nullArg ? nullptr : &pixmap));
        break;
    }
    default: {
        TQ3Pixmap pixmap{};
        STATUS(Q3PixmapDrawContext_GetPixmap(context, nullArg ? nullptr : &pixmap));
        QUERY(Q3DrawContext_GetType(context), TQ3ObjectType{kQ3ObjectTypeInvalid});
        break;
    }
    }
}

TQ3ObjectType Session::rendererType()
{
    static const TQ3ObjectType kTypes[] = {kQ3RendererTypeInteractive, kQ3RendererTypeWireFrame,
                                           kQ3RendererTypeGeneric, kQ3ObjectTypeView, 0};
    const std::uint8_t which = m_in.u8();
    return which < 250 ? kTypes[which % 5] : TQ3ObjectType(static_cast<std::int32_t>(m_in.u32()));
}

void Session::renderer()
{
    if (m_in.u8() < 128) {
        const TQ3Object renderer = OBJECT(Q3Renderer_NewFromType(rendererType()));
        if (renderer != nullptr)
            hold(renderer, Kind::kRenderer);
        return;
    }
    const TQ3Object renderer = pick(Kind::kRenderer);
    const bool nullArg = m_in.u8() == 0;
    TQ3CSGEquation equation{};
    setRaw(equation, static_cast<std::int32_t>(m_in.u32()));
    long vendor = 0, engine = 0;
    TQ3Boolean bypass{};
    unsigned long value = 0;
    switch (m_in.u8() % 10) {
    case 0: STATUS(Q3InteractiveRenderer_SetCSGEquation(renderer, equation)); break;
    case 1: STATUS(Q3InteractiveRenderer_GetCSGEquation(renderer, nullArg ? nullptr : &equation)); break;
    case 2: STATUS(Q3InteractiveRenderer_SetPreferences(renderer, long(m_in.u32()), long(m_in.u32()))); break;
    case 3: STATUS(Q3InteractiveRenderer_GetPreferences(renderer, nullArg ? nullptr : &vendor, &engine)); break;
    case 4: STATUS(q3fuzz_SetDoubleBufferBypass(renderer, enumValue(2))); break;
    case 5: STATUS(Q3InteractiveRenderer_GetDoubleBufferBypass(renderer, nullArg ? nullptr : &bypass)); break;
    case 6: STATUS(Q3InteractiveRenderer_SetRAVEContextHints(renderer, m_in.u32())); break;
    case 7: STATUS(Q3InteractiveRenderer_GetRAVETextureFilter(renderer, nullArg ? nullptr : &value)); break;
    case 8: STATUS(Q3InteractiveRenderer_SetRAVETextureFilter(renderer, m_in.u32())); break;
    default: QUERY(Q3Renderer_GetType(renderer), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
    }
}

void Session::newView()
{
    if (m_views >= kMaxViews)
        return;
    ++m_views;
    const TQ3Object view = OBJECT(Q3View_New());
    if (view == nullptr)
        return;
    hold(view, Kind::kView);
    // Most views get everything they need at once.
    if (m_in.u8() < 200) {
        STATUS(Q3View_SetCamera(view, pick(Kind::kCamera)));
        STATUS(Q3View_SetDrawContext(view, pick(Kind::kDrawContext)));
        STATUS(Q3View_SetRendererByType(view, rendererType()));
    }
}

void Session::viewSet()
{
    const TQ3Object view = pick(Kind::kView);
    switch (m_in.u8() % 4) {
    case 0: STATUS(Q3View_SetCamera(view, pick(Kind::kCamera))); break;
    case 1: STATUS(Q3View_SetDrawContext(view, pick(Kind::kDrawContext))); break;
    case 2: STATUS(Q3View_SetRenderer(view, pick(Kind::kRenderer))); break;
    default: STATUS(Q3View_SetRendererByType(view, rendererType())); break;
    }
}

void Session::viewGet()
{
    const TQ3Object view = pick(Kind::kView);
    const bool nullOut = m_in.u8() == 0;
    TQ3Object got = nullptr;
    Kind kind = Kind::kCamera;
    TQ3Status status = kQ3Failure;
    switch (m_in.u8() % 3) {
    case 0:
        status = STATUS(Q3View_GetCamera(view, nullOut ? nullptr : &got));
        break;
    case 1:
        status = STATUS(Q3View_GetDrawContext(view, nullOut ? nullptr : &got));
        kind = Kind::kDrawContext;
        break;
    default:
        status = STATUS(Q3View_GetRenderer(view, nullOut ? nullptr : &got));
        kind = Kind::kRenderer;
        break;
    }
    if (status == kQ3Success && got != nullptr)
        hold(got, kind);
}

void Session::startRendering()
{
    const TQ3Object view = pick(Kind::kView);
    if (m_loops >= kMaxLoops)
        return;
    ++m_loops;
    STATUS(Q3View_StartRendering(view));
}

void Session::startBounding()
{
    const TQ3Object view = pick(Kind::kView);
    const int mode = enumValue(2);
    if (m_loops >= kMaxLoops)
        return;
    ++m_loops;
    if (m_in.u8() & 1)
        STATUS(q3fuzz_StartBoundingBox(view, mode));
    else
        STATUS(q3fuzz_StartBoundingSphere(view, mode));
}

void Session::endBounding()
{
    const TQ3Object view = pick(Kind::kView);
    const bool nullOut = m_in.u8() == 0;
    if (m_in.u8() & 1) {
        TQ3BoundingBox box;
        std::memset(&box, 0x5A, sizeof box);
        const TQ3BoundingBox untouched = box;
        const TQ3ViewStatus status = VIEWSTATUS(Q3View_EndBoundingBox(view, nullOut ? nullptr : &box));
        if (status == kQ3ViewStatusDone && !box.isEmpty) {
            const float* low = &box.min.x;
            const float* high = &box.max.x;
            for (int i = 0; i < 3; ++i)
                require(low[i] <= high[i], "Q3View_EndBoundingBox", "gave a NaN or inverted box");
        } else if (status != kQ3ViewStatusDone) {
            require(sameBytes(box, untouched), "Q3View_EndBoundingBox", "wrote its result without finishing");
        }
    } else {
        TQ3BoundingSphere sphere;
        std::memset(&sphere, 0x5A, sizeof sphere);
        const TQ3ViewStatus status = VIEWSTATUS(Q3View_EndBoundingSphere(view, nullOut ? nullptr : &sphere));
        if (status == kQ3ViewStatusDone && !sphere.isEmpty)
            require(sphere.radius >= 0.0f, "Q3View_EndBoundingSphere", "gave a NaN or negative radius");
    }
}

void Session::submitRetained()
{
    const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
    const TQ3Object view = pick(Kind::kView);
    const Held* entry = heldEntry(object);
    if (entry != nullptr &&
        (entry->kind == Kind::kCurve || entry->kind == Kind::kPolyLine || isQuadric(entry->kind) ||
         entry->kind == Kind::kPatch) &&
        !drawAllowed())
        return;
    if (entry != nullptr && entry->kind == Kind::kGroup && (!drawAllowed() || !groupIsSmall(object)))
        return;
    const DrawTimer timer(m_drawSeconds);
    switch (m_in.u8() % 3) {
    case 0: STATUS(Q3Geometry_Submit(object, view)); break;
    case 1: STATUS(Q3Object_Submit(object, view)); break;
    default: STATUS(Q3AttributeSet_Submit(object, view)); break;
    }
}

void Session::submitCurveImmediate()
{
    CurveBuffers c;
    readCurve(c);
    const TQ3Object view = pick(Kind::kView);
    if (!drawAllowed())
        return;
    const DrawTimer timer(m_drawSeconds);
    STATUS(Q3NURBCurve_Submit(m_in.u8() == 0 ? nullptr : &c.data, view));
}

void Session::submitStyleImmediate()
{
    bool replaced = false;
    const TQ3SubdivisionStyleData data = readStyle(replaced);
    const TQ3Object view = pick(Kind::kView);
    const TQ3Status status = STATUS(Q3SubdivisionStyle_Submit(m_in.u8() == 0 ? nullptr : &data, view));
    checkStyle("Q3SubdivisionStyle_Submit", status, replaced);
    if (status == kQ3Success) {
        // Unless the loop was cancelled (then the style is ignored), the
        // view's state is now the substituted style.
        TQ3SubdivisionStyleData state{};
        STATUS(Q3View_GetSubdivisionStyleState(view, &state));
    }
}

void Session::submitImmediate()
{
    const TQ3Object view = pick(Kind::kView);
    const bool nullData = m_in.u8() == 0;
    switch (m_in.u8() % 8) {
    case 0: {
        const TQ3Matrix4x4 m = readMatrix();
        STATUS(Q3MatrixTransform_Submit(nullData ? nullptr : &m, view));
        break;
    }
    case 1: {
        const TQ3Vector3D v = vector3();
        STATUS(Q3TranslateTransform_Submit(nullData ? nullptr : &v, view));
        break;
    }
    case 2: {
        const TQ3Vector3D v = vector3();
        STATUS(Q3ScaleTransform_Submit(nullData ? nullptr : &v, view));
        break;
    }
    case 3: {
        TQ3RotateTransformData data{};
        setRaw(data.axis, enumValue(3));
        data.radians = m_in.value();
        STATUS(Q3RotateTransform_Submit(nullData ? nullptr : &data, view));
        break;
    }
    case 4:
        STATUS(Q3ResetTransform_Submit(view));
        break;
    case 5: {
        const TQ3PointData data{point3(), nullptr};
        STATUS(Q3Point_Submit(nullData ? nullptr : &data, view));
        break;
    }
    case 6: {
        const TQ3LineData data{{{point3(), nullptr}, {point3(), nullptr}}, nullptr};
        STATUS(Q3Line_Submit(nullData ? nullptr : &data, view));
        break;
    }
    default: {
        TQ3Vertex3D vertices[4] = {{point3(), nullptr}, {point3(), nullptr}, {point3(), nullptr},
                                   {point3(), nullptr}};
        TQ3PolyLineData data{1u + m_in.u8() % 4, vertices, nullptr, nullptr};
        STATUS(Q3PolyLine_Submit(nullData ? nullptr : &data, view));
        break;
    }
    }
}

void Session::pushPop()
{
    const TQ3Object view = pick(Kind::kView);
    if (m_in.u8() & 1)
        STATUS(Q3Push_Submit(view));
    else
        STATUS(Q3Pop_Submit(view));
}

void Session::decompose()
{
    const TQ3Object geometry = pick(Kind::kCurve);
    const TQ3Object view = pick(Kind::kView);
    if (!drawAllowed())
        return;
    checkDecomposition(geometry, view);
}

void Session::checkDecomposition(TQ3Object geometry, TQ3Object view)
{
    const DrawTimer timer(m_drawSeconds);
    begin();
    const TQ3Object polyline = Q3Geometry_GetDecomposed(geometry, view);
    const bool posted = Q3Error_Get(nullptr) != kQ3ErrorNone;
    checkPosted("Q3Geometry_GetDecomposed", posted);
    if (polyline == nullptr) {
        if (!posted) {
            const Held* entry = heldEntry(geometry);
            require(entry != nullptr && isPrimitiveKind(entry->kind),
                    "Q3Geometry_GetDecomposed", "returned NULL silently for something other than a primitive");
        }
        return;
    }
    const Held* entry = heldEntry(geometry);
    if (entry != nullptr && isQuadric(entry->kind)) {
        require(!posted, "Q3Geometry_GetDecomposed", "posted an error but decomposed");
        checkQuadricDecomposed(entry->kind, geometry, polyline);
        return;
    }
    if (entry != nullptr && entry->kind == Kind::kPatch) {
        require(!posted, "Q3Geometry_GetDecomposed", "posted an error but decomposed");
        checkPatchDecomposed(geometry, polyline);
        return;
    }
    if (holdsKind(geometry, Kind::kPolygon)) {
        // A polygon gives a TriMesh over its own vertices, in order: at
        // most numVertices - 2 triangles when it adds none; a contour that
        // crosses itself is filled by the even-odd rule over points added
        // where its edges cross, and then the count is bounded by the
        // slab decomposition (see boundsEvenOdd).
        require(!posted && Q3Geometry_GetType(polyline) == kQ3GeometryTypeTriMesh, "Q3Geometry_GetDecomposed",
                "a polygon did not give a trimesh");
        hold(polyline, Kind::kTriMesh);
        TQ3PolygonData polygon{};
        TQ3TriMeshData mesh{};
        STATUS(Q3Polygon_GetData(geometry, &polygon));
        STATUS(Q3TriMesh_GetData(polyline, &mesh));
        require(startsWithVertices(mesh, polygon.vertices, polygon.numVertices) &&
                    boundsEvenOdd(mesh, polygon.numVertices, 1),
                "Q3Geometry_GetDecomposed", "a polygon's trimesh has the wrong size");
        STATUS(Q3Polygon_EmptyData(&polygon));
        STATUS(Q3TriMesh_EmptyData(&mesh));
        return;
    }
    if (holdsKind(geometry, Kind::kMesh)) {
        // A mesh gives a TriMesh (empty for a mesh without faces).
        require(!posted && Q3Geometry_GetType(polyline) == kQ3GeometryTypeTriMesh, "Q3Geometry_GetDecomposed",
                "a mesh did not give a trimesh");
        hold(polyline, Kind::kTriMesh);
        return;
    }
    if (entry != nullptr && (entry->kind == Kind::kGeneralPolygon || entry->kind == Kind::kPolyhedron ||
                             entry->kind == Kind::kTriGrid)) {
        checkPolygons2Decomposed(geometry, entry->kind, posted, polyline);
        return;
    }
    require(!posted && holdsKind(geometry, Kind::kCurve), "Q3Geometry_GetDecomposed",
            "decomposed something that is not a curve");
    hold(polyline, Kind::kPolyLine);
    TQ3PolyLineData data{};
    STATUS(Q3PolyLine_GetData(polyline, &data));
    require(data.numVertices >= 2 && data.numVertices <= (unsigned long)kQ3SubdivisionMaxSegmentsPerCurve + 1,
            "Q3Geometry_GetDecomposed", "the polyline's vertex count is outside 2 .. cap + 1");
    STATUS(Q3PolyLine_EmptyData(&data));
}

void Session::checkPolygons2Decomposed(TQ3Object geometry, Kind kind, bool posted, TQ3Object result)
{
    const char* call = "Q3Geometry_GetDecomposed";
    require(!posted && Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "gave no trimesh");
    hold(result, Kind::kTriMesh);
    TQ3TriMeshData mesh{};
    STATUS(Q3TriMesh_GetData(result, &mesh));
    if (kind == Kind::kGeneralPolygon) {
        TQ3GeneralPolygonData data{};
        STATUS(Q3GeneralPolygon_GetData(geometry, &data));
        unsigned long total = 0;
        bool ordered = true;
        for (unsigned long c = 0; c < data.numContours; ++c) {
            const TQ3GeneralPolygonContourData& contour = data.contours[c];
            TQ3TriMeshData rest = mesh;
            rest.numPoints = mesh.numPoints >= total ? mesh.numPoints - total : 0;
            rest.points = mesh.points + (mesh.numPoints >= total ? total : 0);
            ordered = ordered && startsWithVertices(rest, contour.vertices, contour.numVertices);
            total += contour.numVertices;
        }
        require(ordered && boundsEvenOdd(mesh, total, data.numContours), call,
                "a general polygon's trimesh has the wrong size");
        STATUS(Q3GeneralPolygon_EmptyData(&data));
    } else if (kind == Kind::kTriGrid) {
        TQ3TriGridData data{};
        STATUS(Q3TriGrid_GetData(geometry, &data));
        const unsigned long facets = 2 * (data.numRows - 1) * (data.numColumns - 1);
        require(mesh.numTriangles == facets && mesh.numPoints == 3 * facets, call,
                "a grid's trimesh has the wrong size");
        STATUS(Q3TriGrid_EmptyData(&data));
    } else {
        TQ3PolyhedronData data{};
        STATUS(Q3Polyhedron_GetData(geometry, &data));
        require(mesh.numTriangles == data.numTriangles &&
                    mesh.numPoints == 3 * data.numTriangles + 2 * data.numEdges,
                call, "a polyhedron's trimesh has the wrong size");
        STATUS(Q3Polyhedron_EmptyData(&data));
    }
    STATUS(Q3TriMesh_EmptyData(&mesh));
}

void Session::viewState()
{
    const TQ3Object view = pick(Kind::kView);
    const bool nullOut = m_in.u8() == 0;
    if (m_in.u8() & 1) {
        TQ3Matrix4x4 m;
        STATUS(Q3View_GetLocalToWorldMatrixState(view, nullOut ? nullptr : &m));
    } else {
        TQ3SubdivisionStyleData style;
        STATUS(Q3View_GetSubdivisionStyleState(view, nullOut ? nullptr : &style));
    }
}

void Session::cancelSync()
{
    const TQ3Object view = pick(Kind::kView);
    if (m_in.u8() & 1)
        STATUS(Q3View_Cancel(view));
    else
        STATUS(Q3View_Sync(view));
}

void Session::objectQueries()
{
    const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
    constexpr TQ3ObjectType kInvalid = kQ3ObjectTypeInvalid;
    switch (m_in.u8() % 11) {
    case 0: QUERY(Q3Object_GetType(object), kInvalid); break;
    case 1: QUERY(Q3Object_GetLeafType(object), kInvalid); break;
    case 2: QUERY(Q3Object_IsType(object, TQ3ObjectType(static_cast<std::int32_t>(m_in.u32()))), kQ3False); break;
    case 3: QUERY(Q3Object_IsDrawable(object), kQ3False); break;
    case 4: QUERY(Q3Shared_GetType(object), kInvalid); break;
    case 5: QUERY(Q3Shared_IsReferenced(object), kQ3False); break;
    case 6: QUERY(Q3Shared_GetEditIndex(object), 0UL); break;
    case 7: STATUS(Q3Shared_Edited(object)); break;
    case 8: QUERY(Q3Shape_GetType(object), kInvalid); break;
    case 9: QUERY(Q3Geometry_GetType(object), kInvalid); break;
    default: QUERY(Q3Camera_GetType(object), kInvalid); break;
    }
}

void Session::initializeExit()
{
    if (m_in.u8() & 1) {
        if (m_initialized >= 3)
            return;
        begin();
        Q3Initialize();
        require(g_posts.errors == 0, "Q3Initialize", "posted an error");
        require((g_posts.notices == 1) == (m_initialized > 0), "Q3Initialize", "the nesting notice is wrong");
        ++m_initialized;
        return;
    }
    const TQ3Status status = STATUS(Q3Exit());
    require((status == kQ3Success) == (m_initialized > 0), "Q3Exit", "disagrees about being initialized");
    if (m_initialized > 0)
        --m_initialized;
}

} // namespace q3fuzz

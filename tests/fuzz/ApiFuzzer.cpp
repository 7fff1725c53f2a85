// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// libFuzzer target: random sequences of Q3's public C API, decoded from the
// fuzzer's bytes (format: FuzzInput.h). It plays a careless C caller that
// never corrupts memory itself: it passes arbitrary values, NULL, disposed
// handles, stray pointers and objects of the wrong class, but every array
// it passes is as long as the counts it claims (Q3 cannot check that), and
// it never releases a reference it does not hold (no reference count can
// survive that).
//
// Besides the sanitizers, it aborts when Q3 breaks the contract its headers
// state:
//   - a call that fails (kQ3Failure, NULL, kQ3ViewStatusError, or a query's
//     fallback) posts exactly one error, readable with Q3Error_Get and with a
//     message; a call that succeeds posts none; kQ3ErrorInternalError (an
//     unexpected exception) is never posted;
//   - a failed edit leaves the object and its edit index unchanged, a failed
//     getter leaves its output unchanged; a successful edit reads back;
//   - a subdivision style is substituted exactly as QD3DStyle.h says, with
//     one warning when anything was replaced;
//   - the other styles, the shaders' uv settings and the lights accept
//     exactly the values their headers' rules allow, on every path;
//   - a decomposed curve has at most kQ3SubdivisionMaxSegmentsPerCurve + 1
//     vertices, a decomposed quadric or solid at most
//     kQ3SubdivisionMaxTrianglesPerSurface triangles, all finite; a bounding
//     box is never NaN;
//   - after every input, once the fuzzer has disposed what it holds,
//     Q3Memory_CountLiveObjects() is 0 and the last Q3Exit warns of nothing.
// Work per input is bounded (control points, curve draws, loops, views) so
// that no input takes more than a fraction of libFuzzer's -timeout.

#include "FuzzSession.h"

#include <cstdlib>

namespace q3fuzz {

void Session::run()
{
    require(Q3Memory_CountLiveObjects() == 0, "start of input", "objects alive from a previous input");
    begin();
    Q3Initialize();
    require(g_posts.notices == 0 && g_posts.errors == 0, "Q3Initialize", "posted something");
    m_initialized = 1;
    for (int n = 0; n < kMaxOperations && !m_in.atEnd(); ++n)
        step(static_cast<Op>(m_in.u8() % kOpCount));
    finish();
}

void Session::step(Op op)
{
    if (g_trace)
        std::fprintf(stderr, "q3 fuzz: op %u\n", unsigned(op));
    switch (op) {
    case Op::kNewCurve: newCurve(); break;
    case Op::kCurveSetData: curveSetData(); break;
    case Op::kCurveGetData: curveGetData(); break;
    case Op::kSetKnot: setKnot(); break;
    case Op::kGetKnot: getKnot(); break;
    case Op::kSetControlPoint: setControlPoint(); break;
    case Op::kGetControlPoint: getControlPoint(); break;
    case Op::kDuplicate: duplicate(); break;
    case Op::kDispose: dispose(); break;
    case Op::kGetReference: getReference(); break;
    case Op::kNewStyle: newStyle(); break;
    case Op::kStyleSetGet: styleSetGet(); break;
    case Op::kNewTransform: newTransform(); break;
    case Op::kNewAttributeSet: attributeSet(); break;
    case Op::kNewOtherGeometry: otherGeometry(); break;
    case Op::kNewCamera: newCamera(); break;
    case Op::kCameraEdit: cameraEdit(); break;
    case Op::kNewDrawContext: newDrawContext(); break;
    case Op::kDrawContextEdit: drawContextEdit(); break;
    case Op::kNewRenderer: renderer(); break;
    case Op::kNewView: newView(); break;
    case Op::kViewSet: viewSet(); break;
    case Op::kViewGet: viewGet(); break;
    case Op::kStartRendering: startRendering(); break;
    case Op::kEndRendering: {
        const TQ3Object view = pick(Kind::kView);
        const DrawTimer timer(m_drawSeconds);
        VIEWSTATUS(Q3View_EndRendering(view));
        break;
    }
    case Op::kStartBounding: startBounding(); break;
    case Op::kEndBounding: endBounding(); break;
    case Op::kSubmitRetained: submitRetained(); break;
    case Op::kSubmitCurveImmediate: submitCurveImmediate(); break;
    case Op::kSubmitStyleImmediate: submitStyleImmediate(); break;
    case Op::kSubmitTransformImmediate: submitImmediate(); break;
    case Op::kPushPop: pushPop(); break;
    case Op::kDecompose: decompose(); break;
    case Op::kViewState: viewState(); break;
    case Op::kCancelSync: cancelSync(); break;
    case Op::kObjectQueries: objectQueries(); break;
    case Op::kInitializeExit: initializeExit(); break;
    case Op::kOtherGeometryEdit: otherGeometryEdit(); break;
    case Op::kMath: math(); break;
    case Op::kAccessors: accessors(); break;
    case Op::kSurfaces: surfaces(); break;
    case Op::kGroups: groups(); break;
    case Op::kStylesShadersLights: stylesShadersLights(); break;
    case Op::kCurveTools: curveTools(); break;
    case Op::kQuadrics: quadrics(); break;
    case Op::kMeshes: meshes(); break;
    case Op::kPatches: patches(); break;
    case Op::kPolygons2: polygons2(); break;
    case Op::kPixmapMarkers: pixmapMarkers(); break;
    case Op::kViewHints: viewHints(); break;
    case Op::kPicking: picking(); break;
    case Op::kControllers: controllers(); break;
    case Op::kElements: elements(); break;
    case Op::kDescribed: described(); break;
    case Op::kPortable: portable(); break;
    case Op::kCount: break;
    }
}

void Session::duplicate()
{
    const TQ3Object original = pick(Kind(m_in.u8() % kKindCount));
    if (++m_duplicates > kMaxDuplicates)
        return;
    if (holdsKind(original, Kind::kGroup) && !groupIsSmall(original))
        return;
    const TQ3Object copy = OBJECT(Q3Object_Duplicate(original));
    if (copy == nullptr)
        return;
    const Held* entry = heldEntry(original);
    require(entry != nullptr && copy != original, "Q3Object_Duplicate", "copied something it should reject");
    hold(copy, entry->kind);
    const auto shape = m_curves.find(original);
    if (shape != m_curves.end()) {
        const CurveShape copied = shape->second;
        m_curves[copy] = copied;
        TQ3NURBCurveData data{};
        STATUS(Q3NURBCurve_GetData(original, &data));
        TQ3AttributeSet originalSet = data.curveAttributeSet;
        // The copy has a copy of the attribute set, not the same one.
        TQ3NURBCurveData copyData{};
        STATUS(Q3NURBCurve_GetData(copy, &copyData));
        require(copyData.order == data.order && copyData.numPoints == data.numPoints &&
                    std::memcmp(copyData.controlPoints, data.controlPoints,
                                data.numPoints * sizeof(TQ3RationalPoint4D)) == 0 &&
                    std::memcmp(copyData.knots, data.knots, (data.numPoints + data.order) * sizeof(float)) == 0,
                "Q3Object_Duplicate", "the copy of a curve differs from it");
        require((originalSet == nullptr) == (copyData.curveAttributeSet == nullptr) &&
                    (originalSet == nullptr || originalSet != copyData.curveAttributeSet),
                "Q3Object_Duplicate", "the copy does not have its own attribute set");
        STATUS(Q3NURBCurve_EmptyData(&data));
        STATUS(Q3NURBCurve_EmptyData(&copyData));
    }
}

void Session::dispose()
{
    const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
    for (int times = 1 + m_in.u8() % 2; times > 0; --times) {
        const bool held = holds(object);
        // Disposing again after the last held reference went is a double
        // dispose only if the object is gone; if another object still
        // holds it, it would release a reference that is not ours.
        if (!held && object != nullptr && m_initialized > 0 && !isDead(object))
            break;
        const TQ3Status status = STATUS(Q3Object_Dispose(object));
        if (m_initialized == 0)
            continue;
        if (held) {
            require(status == kQ3Success, "Q3Object_Dispose", "failed on a held reference");
            release(object);
        } else {
            require(status == kQ3Failure, "Q3Object_Dispose", "disposed something nobody held");
            const TQ3Error expected = object == nullptr ? kQ3ErrorNULLParameter : kQ3ErrorInvalidObject;
            require(Q3Error_Get(nullptr) == expected, "Q3Object_Dispose", "posted the wrong error");
        }
    }
}

void Session::getReference()
{
    const TQ3Object object = pick(Kind(m_in.u8() % kKindCount));
    const TQ3Object reference = OBJECT(Q3Shared_GetReference(object));
    if (reference == nullptr)
        return;
    const Held* entry = heldEntry(object);
    require(entry != nullptr && reference == object, "Q3Shared_GetReference", "referenced something odd");
    hold(reference, entry->kind);
    begin();
    require(Q3Shared_IsReferenced(object) == kQ3True, "Q3Shared_IsReferenced", "missed a second reference");
}

TQ3SubdivisionStyleData Session::readStyle(bool& replaced)
{
    TQ3SubdivisionStyleData data{};
    const std::int32_t method = enumValue(3);
    setRaw(data.method, method);
    data.c1 = m_in.value();
    data.c2 = m_in.value();
    replaced = false;
    m_expectedStyle = data;
    m_expectedStyle.c1 = expectedParameter(method, data.c1, replaced);
    m_expectedStyle.c2 = expectedParameter(method, data.c2, replaced);
    m_styleValid = method >= 0 && method <= 2;
    return data;
}

void Session::finish()
{
    while (m_initialized == 0) {
        begin();
        Q3Initialize();
        ++m_initialized;
    }
    while (!m_held.empty()) {
        const TQ3Object object = m_held.back().handle;
        if (STATUS(Q3Object_Dispose(object)) != kQ3Success)
            die("Q3Object_Dispose", "failed to release a held reference at the end");
        m_held.pop_back();
    }
    require(Q3Memory_CountLiveObjects() == 0, "end of input", "objects are still alive: a leak");
    for (; m_initialized > 0; --m_initialized) {
        if (STATUS(Q3Exit()) != kQ3Success)
            die("Q3Exit", "failed");
        require(g_posts.warnings == 0, "Q3Exit", "warned at the end of a leak-free input");
    }
}

} // namespace q3fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    q3fuzz::g_trace = std::getenv("Q3_FUZZ_TRACE") != nullptr;
    Q3Error_Register(&q3fuzz::onError, 0);
    Q3Warning_Register(&q3fuzz::onWarning, 0);
    Q3Notice_Register(&q3fuzz::onNotice, 0);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    q3fuzz::Reader in(data, size);
    q3fuzz::Session(in).run();
    return 0;
}

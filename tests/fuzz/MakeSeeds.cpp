// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Writes the API fuzzer's seed corpus: one small input per scenario, each a
// sensible use of the API (the article's Listing 1 drawn in retained and
// immediate mode, bounded, decomposed) or one class of bad input from
// docs/robustness.md. Usage: q3_fuzz_seeds DIRECTORY. Run with
// Q3_FUZZ_TRACE=1 q3_fuzz_api FILE to see what a seed decodes to.

#include "FuzzInput.h"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

using q3fuzz::Op;

// Kinds, in the fuzzer's order (for the kind byte of kDuplicate and others).
enum Kind : std::uint8_t { kCurve, kPolyLine, kLine, kPoint, kStyle, kTransform, kAttributeSet, kCamera,
                           kDrawContext, kRenderer, kView, kTriangle, kPolygon, kTriMesh, kOtherStyle, kShader,
                           kLight, kGroup, kBox, kCone, kCylinder, kDisk, kEllipse, kEllipsoid, kTorus, kMesh, kPatch,
                           kGeneralPolygon, kPolyhedron, kTriGrid, kMarker, kPixmapMarker, kViewHints, kPick };

enum Style : std::uint8_t { kConstant = 0, kWorld = 1, kScreen = 2, kBadMethod = 3 };

struct Patch {
    std::uint8_t target; // bit 0: knot; bits 6-7: point component
    float value;
    std::uint16_t index;
};

// Each method writes one operation exactly as ApiFuzzer.cpp reads it.
class Seed : public q3fuzz::BasicWriter<Seed> {
public:
    // Described data (FuzzInput.h), with the palette NULL and no sets.
    Seed& newPoint(float x, float y, float z) { return op(Op::kNewOtherGeometry).u8(0).null().xyz(x, y, z).noSet(); }
    Seed& newLine(float x0, float y0, float z0, float x1, float y1, float z1)
    {
        return op(Op::kNewOtherGeometry).u8(1).null().vertex(x0, y0, z0).vertex(x1, y1, z1).noSet();
    }
    // xyz: the vertices' coordinates; no segment sets.
    Seed& newPolyLine(const std::vector<float>& xyz)
    {
        op(Op::kNewOtherGeometry).u8(2).null().count(std::uint8_t(xyz.size() / 3)).noSet().array();
        for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
            vertex(xyz[i], xyz[i + 1], xyz[i + 2]);
        return noArray();
    }
    // surfaces(): the family (0 triangle, 1 polygon), the action, the
    // non-null byte, the data (vertices from xyz, no sets).
    Seed& surface(std::uint8_t family, std::uint8_t action, const std::vector<float>& xyz)
    {
        op(Op::kSurfaces).u8(family).u8(action).u8(1).null();
        if (family == 1)
            count(std::uint8_t(xyz.size() / 3)).noSet().array();
        for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
            vertex(xyz[i], xyz[i + 1], xyz[i + 2]);
        return family == 0 ? noSet() : *this;
    }
    // A quadric's described data: a valid shape (axes along y, z and x, a
    // torus's tube half as thick, full ranges, every cap) with the floats
    // `changes` names (index in the struct's float fields) replaced, no
    // sets (a box's six face sets an array of NULLs).
    Seed& quadricData(std::uint8_t type, const std::vector<std::pair<int, float>>& changes = {})
    {
        std::vector<float> floats = {0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 1};
        if (type == 3 || type == 4) // no orientation; an ellipse no v range
            floats.erase(floats.begin() + 3, floats.begin() + 6);
        if (type == 4)
            floats.resize(11);
        if (type == 6)
            floats = {0, 0, 0, 0, 0.5f, 0, 0, 0, 1, 1, 0, 0, 0.5f, 0, 1, 0, 1};
        for (const auto& [index, v] : changes)
            floats[std::size_t(index)] = v;
        null();
        for (float v : floats)
            value(v);
        static const std::uint8_t kSets[] = {1, 4, 5, 1, 1, 2, 2};
        if (type == 1 || type == 2 || type == 5 || type == 6)
            u8(7);
        for (int i = 0; i < kSets[type]; ++i)
            noSet();
        if (type == 0) {
            array();
            for (int i = 0; i < 6; ++i)
                noSet();
        }
        return *this;
    }

    Seed& listing1Curve(const std::vector<Patch>& patches = {}, std::uint8_t flags = 0)
    {
        u8(q3fuzz::kCurveListing1 | flags).u8(3);
        writePatches(patches);
        return curveTail(flags);
    }

    // A clamped uniform curve of order + extra points on a shape (bits: 1
    // weights, 2 cos, 4 sin, 8 helix, 16 unclamped knots).
    Seed& generatedCurve(std::uint8_t order, std::uint16_t extra, float scale, std::uint8_t shape,
                         const std::vector<Patch>& patches = {}, std::uint8_t flags = 0)
    {
        u8(q3fuzz::kCurveGenerated | flags).u8(order - 1).u16(extra).value(scale).u8(shape);
        writePatches(patches);
        return curveTail(flags);
    }

    // Every value given: count points (x, y, z, w), the first knot and
    // count + order knot steps.
    Seed& rawCurve(std::uint8_t order, const std::vector<float>& xyzw, float firstKnot,
                   const std::vector<std::uint8_t>& steps, std::uint8_t flags = 0)
    {
        u8(q3fuzz::kCurveRaw | flags).u8(order - 1).u8(std::uint8_t(xyzw.size() / 4));
        for (float v : xyzw)
            value(v);
        value(firstKnot);
        for (std::uint8_t s : steps)
            u8(s);
        return curveTail(flags);
    }

    // curveTools(): the form (object: the first held curve; data: Listing 1), then
    // the arguments in the order ApiFuzzer.cpp reads them; xyz are the points to fit.
    Seed& curveTool(bool object, std::uint8_t which, float a, float b, float tolerance, std::uint8_t index,
                    std::uint8_t times, const std::vector<float>& knots = {}, const std::vector<float>& xyz = {})
    {
        op(Op::kCurveTools).u8(object ? 1 : 0);
        if (object)
            held();
        else
            listing1Curve();
        u8(1).u8(1).value(a).value(b).value(tolerance).smallIndex(index).smallIndex(times).u8(which);
        u8(std::uint8_t(knots.size()));
        for (float k : knots)
            value(k);
        u8(std::uint8_t(xyz.size() / 3));
        for (float v : xyz)
            value(v);
        return u8(1).u8(3).u8(0).value(1).value(2).value(0).u8(1);  // order 4, chord length, target, two halves
    }

    Seed& newCurveListing1(const std::vector<Patch>& patches = {})
    {
        op(Op::kNewCurve);
        return listing1Curve(patches);
    }

    // Camera, 64 x 64 ARGB32 pixmap draw context, view with an interactive
    // renderer; cameraKind 0 orthographic (Listing 1 framed), 1 view plane,
    // 2 view angle aspect.
    Seed& scene(std::uint8_t cameraKind = 0, std::uint16_t size = 64)
    {
        op(Op::kNewCamera).u8(1).u8(cameraKind).u8(0).u8(0);
        op(Op::kNewDrawContext);
        drawContextData();
        pixmap(1, std::uint8_t(size), std::uint8_t(size));
        u8(1);
        op(Op::kNewView).u8(0).held().held().u8(0);
        return *this;
    }

    Seed& drawContextData()
    {
        u8(1);                             // clear with colour
        value(1).value(0).value(0).value(0); // opaque black
        value(0).value(0).value(64).value(64);
        return u8(0).u8(0).u8(0);          // pane, mask and double buffer off
    }

    Seed& pixmap(std::uint8_t type, std::uint8_t width, std::uint8_t height, std::uint8_t shape = 0)
    {
        u8(shape).u8(type);
        if (shape & 1)
            u8(32);
        if (shape & 2)
            u16(width).u8(height);
        else
            u8(width).u8(height);
        u8(0);
        if (shape & 4)
            u16(width);
        return u8(0).u8(0);
    }

    Seed& style(std::uint8_t method, float c1, float c2 = 20.0f) { return u8(method).value(c1).value(c2); }

    Seed& startRendering() { op(Op::kStartRendering).held(); return *this; }
    Seed& endRendering() { op(Op::kEndRendering).held(); return *this; }
    Seed& startBox(std::uint8_t mode = 0) { op(Op::kStartBounding).held().u8(mode).u8(1); return *this; }
    Seed& endBox() { op(Op::kEndBounding).held().u8(1).u8(1); return *this; }
    Seed& startSphere(std::uint8_t mode = 0) { op(Op::kStartBounding).held().u8(mode).u8(0); return *this; }
    Seed& endSphere() { op(Op::kEndBounding).held().u8(1).u8(0); return *this; }

    Seed& submitHeld(Kind kind, std::uint8_t which = 0, std::uint8_t call = 0)
    {
        op(Op::kSubmitRetained).u8(kind).held(which).held().u8(call);
        return *this;
    }
    Seed& submitStyle(std::uint8_t method, float c1)
    {
        op(Op::kSubmitStyleImmediate);
        style(method, c1);
        held().u8(1);
        return *this;
    }
    Seed& decompose(std::uint8_t which = 0)
    {
        op(Op::kDecompose).held(which).held();
        return *this;
    }
    Seed& dispose(Kind kind, std::uint8_t which = 0, bool twice = false)
    {
        op(Op::kDispose).u8(kind).held(which).u8(twice ? 1 : 0);
        return *this;
    }

private:
    void writePatches(const std::vector<Patch>& patches)
    {
        u8(std::uint8_t(patches.size()));
        for (const Patch& p : patches)
            u8(p.target).value(p.value).u16(p.index);
    }

    Seed& curveTail(std::uint8_t flags)
    {
        if (flags & q3fuzz::kCurveShortCount)
            u16(2);
        if (flags & q3fuzz::kCurveHugeCount)
            u8(0);
        if (flags & q3fuzz::kCurveAttributes)
            held();
        return *this;
    }
};

constexpr float kNaN = __builtin_nanf("");
constexpr float kInf = __builtin_inff();

std::vector<std::pair<std::string, Seed>> seeds()
{
    std::vector<std::pair<std::string, Seed>> all;
    auto add = [&](const char* name) -> Seed& {
        all.emplace_back(name, Seed{});
        return all.back().second;
    };

    // The article's Listing 1, retained: New, render, dispose.
    add("listing1-retained").scene().newCurveListing1().startRendering().submitHeld(kCurve).endRendering()
        .dispose(kCurve);
    // The same curve in immediate mode, then bounded as a box and a sphere.
    {
        Seed& s = add("listing1-immediate");
        s.scene().startRendering();
        s.op(Op::kSubmitCurveImmediate).listing1Curve().held().u8(1);
        s.endRendering();
    }
    add("listing1-bounds").newCurveListing1().op(Op::kNewView).u8(255);
    all.back().second.startBox().submitHeld(kCurve).endBox().startSphere(1).submitHeld(kCurve).endSphere();
    // Decomposed under each subdivision method.
    {
        Seed& s = add("listing1-decompose");
        s.scene().newCurveListing1().startRendering();
        s.submitStyle(kConstant, 10).decompose().submitStyle(kWorld, 0.1f).decompose();
        s.submitStyle(kScreen, 2).decompose().endRendering();
    }
    // Perspective cameras.
    add("listing1-viewplane").scene(1).newCurveListing1().startRendering().submitHeld(kCurve).endRendering();
    add("listing1-viewangle").scene(2).newCurveListing1().startRendering().submitHeld(kCurve).endRendering();
    // The largest curve an input may make: 4096 points of order 16, drawn
    // with as many constant segments as allowed (the segment cap).
    {
        Seed& s = add("huge-curve-constant");
        s.scene().op(Op::kNewCurve).generatedCurve(16, 4080, 1.5f, 2 | 4);
        s.startRendering().submitStyle(kConstant, 1024).submitHeld(kCurve).decompose().endRendering();
    }
    // A world-space c1 a million times smaller than the curve.
    {
        Seed& s = add("tiny-world-c1");
        s.scene().newCurveListing1().startRendering().submitStyle(kWorld, 3e-6f).decompose().endRendering();
    }
    // A perspective camera inside a helix around it.
    {
        Seed& s = add("camera-inside-curve");
        s.op(Op::kNewCamera).u8(1).u8(2).u8(1);
        s.value(0).value(0).value(0).value(0).value(0).value(-1).value(0).value(1).value(0);
        s.value(0.01f).value(100).value(-1).value(1).value(2).value(2).u8(0);
        s.op(Op::kNewDrawContext).drawContextData().pixmap(1, 64, 64).u8(1);
        s.op(Op::kNewView).u8(0).held().held().u8(0);
        s.op(Op::kNewCurve).generatedCurve(4, 200, 3.0f, 2 | 4 | 8);
        s.startRendering().submitStyle(kScreen, 0.5f);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(1).value(0).value(0).value(-300);
        s.submitHeld(kCurve).decompose().endRendering();
    }
    // Style substitutions: NaN, infinity, zero, negative, too many segments.
    {
        Seed& s = add("style-substitutions");
        s.op(Op::kNewStyle).u8(kConstant).special(0).special(1);
        s.op(Op::kNewStyle).u8(kWorld).value(0).value(-1);
        s.op(Op::kNewStyle).u8(kScreen).special(2).value(-0.25f);
        s.op(Op::kNewStyle).u8(kConstant).value(2000).special(7);
        s.op(Op::kStyleSetGet).held().style(kConstant, 0.5f).u8(1).u8(1);
    }
    {
        Seed& s = add("style-bad-method");
        s.op(Op::kNewStyle).u8(kBadMethod).value(1).value(1);
        s.op(Op::kNewStyle).u8(255).u32(0x7FFFFFFF).value(1).value(1);
        s.op(Op::kNewStyle).u8(kWorld).value(1).value(1);
        s.op(Op::kStyleSetGet).held().u8(255).u32(0xFFFFFFFF).value(2).value(2).u8(1).u8(1);
    }
    // Knot edits at 0, the last index, one past it and UINT32_MAX, with good
    // values, NaN, infinity and ones that break the knot rules.
    {
        Seed& s = add("knot-edits");
        s.newCurveListing1();
        s.op(Op::kSetKnot).held().smallIndex(0).value(-1);
        s.op(Op::kSetKnot).held().u8(1).value(2);
        s.op(Op::kSetKnot).held().u8(2).value(1);
        s.op(Op::kSetKnot).held().rawIndex(0xFFFFFFFF).value(1);
        s.op(Op::kSetKnot).held().smallIndex(3).special(0);
        s.op(Op::kSetKnot).held().smallIndex(4).special(1);
        s.op(Op::kSetKnot).held().smallIndex(4).value(0);
        s.op(Op::kSetKnot).held().smallIndex(4).value(0.5f);
        s.op(Op::kGetKnot).held().u8(2).u8(1);
        s.op(Op::kGetKnot).held().rawIndex(0xFFFFFFFF).u8(1);
        s.op(Op::kGetKnot).held().smallIndex(0).u8(0);
    }
    {
        Seed& s = add("control-point-edits");
        s.newCurveListing1();
        s.op(Op::kSetControlPoint).held().smallIndex(1).value(5).value(5).value(5).value(2).u8(1);
        s.op(Op::kSetControlPoint).held().u8(1).value(1).value(1).value(1).value(0).u8(1);
        s.op(Op::kSetControlPoint).held().u8(2).value(1).value(1).value(1).value(1).u8(1);
        s.op(Op::kSetControlPoint).held().smallIndex(0).special(0).value(1).value(1).value(1).u8(1);
        s.op(Op::kSetControlPoint).held().smallIndex(0).value(1).value(1).value(1).value(-1).u8(1);
        s.op(Op::kSetControlPoint).held().rawIndex(0xFFFFFFFF).value(1).value(1).value(1).value(1).u8(1);
        s.op(Op::kSetControlPoint).held().smallIndex(0).value(1).value(1).value(1).value(1).u8(0);
        s.op(Op::kGetControlPoint).held().u8(1).u8(1);
        s.op(Op::kGetControlPoint).held().u8(2).u8(1);
    }
    // Whole-curve data: SetData with good and bad data, GetData, EmptyData.
    {
        Seed& s = add("curve-set-get-data");
        s.newCurveListing1();
        s.op(Op::kCurveSetData).held().generatedCurve(3, 10, 2.0f, 1).u8(1);
        s.op(Op::kCurveSetData).held().generatedCurve(17, 10, 2.0f, 0).u8(1);
        s.op(Op::kCurveSetData).held().generatedCurve(1, 10, 2.0f, 0).u8(1);
        s.op(Op::kCurveSetData).held().listing1Curve({}, q3fuzz::kCurveShortCount).u8(1);
        s.op(Op::kCurveSetData).held().listing1Curve({}, q3fuzz::kCurveHugeCount).u8(1);
        s.op(Op::kCurveSetData).held().listing1Curve({}, q3fuzz::kCurveNullPoints).u8(1);
        s.op(Op::kCurveSetData).held().listing1Curve({}, q3fuzz::kCurveNullKnots).u8(1);
        s.op(Op::kCurveSetData).held().listing1Curve().u8(0);
        s.op(Op::kCurveGetData).held().u8(1).u8(0);
        s.op(Op::kCurveGetData).held().u8(0).u8(1);
    }
    // Bad knot vectors: decreasing, too long a run, NaN, empty domain.
    {
        Seed& s = add("bad-knot-vectors");
        s.newCurveListing1({{1, 2.0f, 1}});
        s.newCurveListing1({{1, 0.0f, 4}, {1, 0.0f, 5}, {1, 0.0f, 6}, {1, 0.0f, 7}});
        s.newCurveListing1({{1, kNaN, 3}});
        s.newCurveListing1({{1, kInf, 7}});
        s.op(Op::kNewCurve).generatedCurve(4, 6, 1.0f, 0, {{1, 1.0f, 5}, {1, 1.0f, 6}, {1, 1.0f, 7}});
    }
    // Bad control points: NaN, infinity, zero and negative weights.
    {
        Seed& s = add("bad-control-points");
        s.newCurveListing1({{0, kNaN, 0}});
        s.newCurveListing1({{64, kInf, 1}});
        s.newCurveListing1({{192, 0.0f, 2}});
        s.newCurveListing1({{192, -1.0f, 3}});
        s.op(Op::kNewCurve).rawCurve(2, {0, 0, 0, 1, 1, 1, 1, 1}, 0, {0, 1, 0, 0});
        s.op(Op::kNewCurve).rawCurve(3, {0, 0, 0, 1, 1, 1, 1, 1}, 0, {0, 0, 1, 0, 0});
    }
    // Handles: duplicate, double dispose, use after dispose, a stray pointer
    // and objects of the wrong class.
    {
        Seed& s = add("handles-lifetime");
        s.newCurveListing1();
        s.op(Op::kDuplicate).u8(kCurve).held();
        s.op(Op::kGetReference).u8(kCurve).held(1);
        s.dispose(kCurve, 0, true);
        s.op(Op::kSetKnot).stale().smallIndex(0).value(0);
        s.op(Op::kDispose).u8(kCurve).stale().u8(1);
        s.op(Op::kGetKnot).stray().smallIndex(0).u8(1);
        s.op(Op::kDispose).u8(kCurve).stray(3).u8(0);
        s.op(Op::kDispose).u8(kCurve).null().u8(0);
        s.op(Op::kObjectQueries).u8(kCurve).stale().u8(1);
        s.op(Op::kObjectQueries).u8(kCurve).held().u8(7);
    }
    {
        Seed& s = add("handles-wrong-class");
        s.op(Op::kNewStyle).u8(kConstant).value(4).value(4);
        s.newCurveListing1();
        s.op(Op::kSetKnot).held(0).smallIndex(0).value(0);
        s.op(Op::kSetKnot).anyHeld(0).smallIndex(0).value(0);
        s.op(Op::kStyleSetGet).anyHeld(1).style(kWorld, 1).u8(1).u8(1);
        s.op(Op::kNewView).u8(255);
        s.op(Op::kSetControlPoint).anyHeld(2).smallIndex(0).value(0).value(0).value(0).value(1).u8(1);
        s.op(Op::kViewSet).anyHeld(1).u8(0).anyHeld(0);
        s.op(Op::kGetReference).u8(kView).anyHeld(2);
        s.op(Op::kDuplicate).u8(kView).anyHeld(2);
        for (std::uint8_t q = 0; q < 11; ++q)
            s.op(Op::kObjectQueries).u8(kView).anyHeld(q % 3).u8(q);
    }
    // Submitting outside a loop, ending loops that never started, unbalanced
    // pops, nested starts, and disposing a view inside its loop.
    {
        Seed& s = add("loops-misuse");
        s.scene().newCurveListing1();
        s.submitHeld(kCurve).op(Op::kPushPop).held().u8(0).endRendering().endBox();
        s.startRendering().startRendering().startBox();
        s.op(Op::kPushPop).held().u8(0).op(Op::kPushPop).held().u8(1).op(Op::kPushPop).held().u8(0);
        s.op(Op::kPushPop).held().u8(0).endBox().endRendering().endRendering();
        s.startRendering().submitHeld(kCurve).op(Op::kCancelSync).held().u8(0).dispose(kView);
    }
    {
        Seed& s = add("view-cancel-sync");
        s.scene().newCurveListing1().startRendering();
        s.op(Op::kCancelSync).held().u8(1).submitHeld(kCurve).op(Op::kCancelSync).held().u8(0);
        s.endRendering().op(Op::kCancelSync).held().u8(0).op(Op::kCancelSync).held().u8(1);
        s.startBox().op(Op::kCancelSync).held().u8(1).endBox();
    }
    // Transforms with NaN and infinities, retained and immediate.
    {
        Seed& s = add("transforms-nonfinite");
        s.scene().newCurveListing1();
        s.op(Op::kNewTransform).u8(1).value(1).value(2).value(3).u8(1);
        s.op(Op::kNewTransform).u8(1).special(0).value(0).value(0).u8(1);
        s.op(Op::kNewTransform).u8(2).special(1).value(1).value(1).u8(1);
        s.op(Op::kNewTransform).u8(3).u8(2).value(0.5f).u8(1);
        s.op(Op::kNewTransform).u8(3).u8(3).value(0.5f).u8(1);
        s.op(Op::kNewTransform).u8(0).u8(0x20).u8(3).u8(3).special(2).u8(1);
        s.op(Op::kNewTransform).u8(4);
        s.op(Op::kNewTransform).u8(5).value(0).value(0).value(0).value(0).value(0).value(0).value(1);
        s.startRendering().submitHeld(kTransform, 0).submitHeld(kTransform, 1).submitHeld(kCurve);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(1).special(1).value(0).value(0);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(2).value(0).value(0).value(0);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(0).u8(1);
        for (int i = 0; i < 16; ++i)
            s.special(std::uint8_t(i == 5 ? 0 : 12));
        s.submitHeld(kCurve).op(Op::kViewState).held().u8(1).u8(1).endRendering();
    }
    // Cameras with every kind of bad value.
    {
        Seed& s = add("cameras-bad-values");
        auto raw = [&](std::uint8_t kind, std::vector<float> values) {
            s.op(Op::kNewCamera).u8(1).u8(kind).u8(1);
            for (float v : values)
                s.value(v);
            s.u8(0);
        };
        raw(0, {kNaN, 0, 10, 0, 0, 0, 0, 1, 0, 1, 100, -1, 1, 2, 2});
        raw(1, {0, 0, 10, 0, 0, 10, 0, 1, 0, 1, 100, -1, 1, 2, 2});
        raw(2, {0, 0, 10, 0, 0, 0, 0, 0, 1, 1, 100, -1, 1, 2, 2});
        raw(2, {0, 0, 10, 0, 0, 0, 0, 1, 0, 0, 100, -1, 1, 2, 2});
        raw(0, {0, 0, 10, 0, 0, 0, 0, 1, 0, 5, 1, -1, 1, 2, 2});
        s.op(Op::kNewCamera).u8(1).u8(2).u8(0).u8(1).value(4).value(1);
        s.op(Op::kNewCamera).u8(1).u8(2).u8(2).u8(13).value(-1).u8(0);
        s.op(Op::kNewCamera).u8(1).u8(0).u8(0).u8(1).value(1).value(0).value(1).value(0);
        s.op(Op::kNewCamera).u8(0).u8(0).u8(0).u8(0);
        s.op(Op::kNewCamera).u8(1).u8(0).u8(0).u8(0);
        for (std::uint8_t which = 0; which < 10; ++which) {
            s.op(Op::kCameraEdit).held().u8(1).u8(2).u8(9).special(0).u8(which);
            if (which == 9)
                s.value(0).value(1);
        }
        s.op(Op::kCameraEdit).held().u8(0).u8(0).u8(2);
    }
    // Bad pixmaps: NULL image, pixel type and size mismatch, zero size, rows
    // too short, wider than the renderer supports.
    {
        Seed& s = add("pixmaps-bad");
        s.op(Op::kNewDrawContext).drawContextData().pixmap(1, 16, 16, 8).u8(1);
        s.op(Op::kNewDrawContext).drawContextData().pixmap(6, 16, 16).u8(1);
        s.op(Op::kNewDrawContext).drawContextData().pixmap(2, 16, 16, 1).u8(1);
        s.op(Op::kNewDrawContext).drawContextData().pixmap(1, 0, 16).u8(1);
        s.op(Op::kNewDrawContext).drawContextData().pixmap(1, 16, 16, 4).u8(1);
        s.op(Op::kNewCamera).u8(1).u8(0).u8(0).u8(0);
        s.op(Op::kNewDrawContext).drawContextData();
        s.u8(2).u8(1).u16(20000).u8(1).u8(0).u8(0).u8(0).u8(1);
        s.op(Op::kNewView).u8(0).held().held().u8(0).startRendering().endRendering();
    }
    {
        Seed& s = add("pixmaps-every-type");
        s.op(Op::kNewCamera).u8(1).u8(0).u8(0).u8(0);
        for (std::uint8_t type = 0; type < 6; ++type)
            s.op(Op::kNewDrawContext).drawContextData().pixmap(type, 33, 17).u8(1);
        s.op(Op::kNewView).u8(0).held().held(3).u8(1).newCurveListing1();
        s.startRendering().submitHeld(kCurve).endRendering();
        s.op(Op::kViewSet).held().u8(1).held(5).startRendering().submitHeld(kCurve).endRendering();
    }
    // Draw context edits: panes (empty, inverted, huge, NaN), clear colours.
    {
        Seed& s = add("draw-context-edits");
        s.scene().newCurveListing1();
        s.op(Op::kDrawContextEdit).held().u8(1);
        s.u8(1).value(1).value(1).value(0).value(0).value(10).value(10).value(50).value(40).u8(1).u8(0).u8(0);
        s.u8(0);
        s.op(Op::kDrawContextEdit).held().u8(1);
        s.u8(1).special(0).value(1).value(0).value(0).value(10).value(10).value(5).value(40).u8(1).u8(0).u8(0);
        s.u8(4);
        s.op(Op::kDrawContextEdit).held().u8(1);
        s.u8(1).value(1).value(1).value(0).value(0).special(6).value(0).special(5).value(40).u8(1).u8(0).u8(0);
        s.u8(0);
        s.op(Op::kDrawContextEdit).held().u8(1).drawContextData().u8(6).u8(2);
        s.op(Op::kDrawContextEdit).held().u8(1).drawContextData().u8(8).u8(255).u32(7);
        s.startRendering().submitHeld(kCurve).endRendering();
    }
    // Renderers: every type code, and the stored interactive settings.
    {
        Seed& s = add("renderers");
        for (std::uint8_t type = 0; type < 5; ++type)
            s.op(Op::kNewRenderer).u8(0).u8(type);
        s.op(Op::kNewRenderer).u8(0).u8(255).u32(0x12345678);
        for (std::uint8_t which = 0; which < 10; ++which) {
            s.op(Op::kNewRenderer).u8(200).held(which % 2).u8(1).u32(0x88888888).u8(which);
            if (which == 2)
                s.u32(5).u32(6);
            else if (which == 4)
                s.u8(2);
            else if (which == 6 || which == 8)
                s.u32(7);
        }
        s.scene().op(Op::kViewSet).held().u8(2).held(1).op(Op::kViewGet).held().u8(1).u8(2);
        s.op(Op::kViewGet).held().u8(1).u8(0).op(Op::kViewGet).held().u8(1).u8(1).op(Op::kViewGet).held().u8(0).u8(0);
    }
    // Attribute sets on curves, submitted, with colours out of range.
    {
        Seed& s = add("attribute-sets");
        s.op(Op::kNewAttributeSet).u8(0).u8(3);
        s.u8(5).value(1).value(0).value(0).value(0).value(0).value(0).value(0).value(0).u8(1).u8(0);
        s.u8(10).value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).u8(2).u8(1).u8(0);
        s.u8(200).value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).u8(1).u8(0);
        s.u8(11).value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).u8(1).u8(0);
        s.op(Op::kNewCurve).listing1Curve({}, q3fuzz::kCurveAttributes);
        s.scene().startRendering().submitHeld(kAttributeSet, 0, 2).submitHeld(kCurve).endRendering();
        s.op(Op::kDuplicate).u8(kCurve).held();
        s.dispose(kAttributeSet).op(Op::kNewCurve).listing1Curve({}, q3fuzz::kCurveAttributes);
    }
    // Points, lines and polylines next to the curves.
    {
        Seed& s = add("other-geometry");
        s.newPoint(1, 1, 1).newLine(0, 0, 0, 1, 1, 0).newPolyLine({0, 0, 0, 1, 0, 0, 1, 1, 0});
        s.newPolyLine({0, 0, 0}); // one vertex: refused
        s.op(Op::kNewOtherGeometry).u8(0).null().special(0).value(1).value(1).noSet(); // NaN: refused
        s.scene().startRendering().submitHeld(kPoint).submitHeld(kLine).submitHeld(kPolyLine);
        s.decompose(0).op(Op::kDecompose).u8(0).u8(1).held();
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(4);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(5).value(1).value(2).value(0);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(6).value(0).value(0).value(0).value(1).value(1).value(1);
        s.op(Op::kSubmitTransformImmediate).held().u8(1).u8(7);
        for (int i = 0; i < 12; ++i)
            s.value(float(i % 3));
        s.u8(2);
        s.endRendering().startBox().submitHeld(kPolyLine).submitHeld(kPoint).endBox();
    }
    // Apple's single-field accessors on points, lines, polylines, transforms
    // and cameras: good values, NaN, indices at the ends and beyond.
    {
        Seed& s = add("accessors");
        s.newPoint(1, 1, 1).newLine(0, 0, 0, 1, 1, 0).newPolyLine({0, 0, 0, 1, 0, 0, 1, 1, 0});
        s.op(Op::kNewTransform).u8(1).value(1).value(2).value(3).u8(1);
        s.scene(2);
        // accessors(): null-argument byte, set/get byte, attribute-set byte, a position, the family.
        auto call = [&s](bool set, std::uint8_t family, float x) -> Seed& {
            return s.op(Op::kAccessors).u8(1).u8(set ? 1 : 0).u8(0).value(x).value(2).value(3).u8(family);
        };
        call(true, 0, 5).held();                      // Q3Point_SetPosition
        call(false, 0, 0).held();                     // Q3Point_GetPosition
        call(true, 1, 4).held().smallIndex(1);        // Q3Line_SetVertexPosition, last end
        call(true, 1, 4).held().rawIndex(0xFFFFFFFFu); // out of range
        call(false, 2, 0).held().smallIndex(0);       // Q3Line_GetVertexAttributeSet
        call(true, 3, 7).held().smallIndex(2);        // Q3PolyLine_SetVertexPosition, last vertex
        call(true, 3, 7).held().smallIndex(3);        // one past the end
        s.op(Op::kAccessors).u8(1).u8(1).u8(0).special(0).value(0).value(0).u8(3).held().smallIndex(1); // NaN
        call(false, 4, 0).held().smallIndex(1).u8(1); // Q3PolyLine_GetSegmentAttributeSet
        call(true, 4, 0).held().rawIndex(0xFFFFFFFFu).u8(1);
        call(false, 5, 0).u8(3).held();               // Q3Geometry_GetAttributeSet of the point
        // transformField(): the transform, a matrix, a vector, an axis, an angle, the field.
        call(true, 6, 0).held().u8(0).value(-1).value(0).value(4).u8(1).value(0.5f).u8(1); // Translate_Set
        call(false, 6, 0).held().u8(0).value(0).value(0).value(0).u8(1).value(0).u8(6);    // GetMatrix
        // cameraField(): the field, the camera, the value.
        call(true, 7, 0).u8(9).held().value(1);       // Q3ViewAngleAspectCamera_SetFOV
        call(true, 7, 0).u8(9).held().special(0);     // NaN
        call(false, 7, 0).u8(10).held().value(0);     // GetAspectRatio
        s.startRendering().submitHeld(kPoint).submitHeld(kLine).submitHeld(kPolyLine).endRendering();
    }
    // Triangles, polygons and trimeshes: made, drawn filled and in
    // wireframe, bounded, decomposed, edited at their index ends and with
    // NaN, emptied twice.
    {
        Seed& s = add("surfaces");
        const std::vector<float> triangle{0, 0, 0, 1, 0, 0, 0, 1, 0};
        s.surface(0, 0, triangle).surface(1, 0, {0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 0.5f, 0, 0, 2, 0}); // concave
        // A trimesh of 4 points and 2 triangles with per-vertex diffuse colours
        // (family, action, attribute-set byte, non-null byte, readTriMesh's data).
        s.op(Op::kSurfaces).u8(2).u8(0).u8(0).u8(1).u8(4);
        for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f})
            s.value(v);
        s.u8(2).smallIndex(0).smallIndex(1).smallIndex(2).smallIndex(0).smallIndex(2).smallIndex(3);
        s.u8(0).u8(1).u8(1).u8(4); // no edges; one array, on the vertices, diffuse colour
        for (int i = 0; i < 4 * 6 + 1; ++i)
            s.u8(1).u8(1);
        s.u8(0).u8(1);
        s.scene(2).startRendering().submitHeld(kTriangle).submitHeld(kPolygon).submitHeld(kTriMesh).endRendering();
        s.startBox().submitHeld(kPolygon).submitHeld(kTriMesh).endBox();
        // No curve is held, so the decomposition takes any held object: the
        // triangle (NULL) and the polygon (a trimesh).
        s.startRendering().op(Op::kDecompose).held(0).held().op(Op::kDecompose).held(1).held().endRendering();
        // vertexCalls(): the geometry, an index, the null byte, a position, the call.
        s.surface(0, 4, triangle).held().smallIndex(2).u8(1).value(5).value(5).value(5).u8(1); // last vertex
        s.surface(0, 4, triangle).held().smallIndex(3).u8(1).special(0).value(0).value(0).u8(1); // past it, NaN
        // SetData with a NaN vertex, then GetData and EmptyData twice.
        s.surface(0, 1, {0, 0, 0, kNaN, 0, 0, 0, 1, 0}).held();
        s.surface(1, 2, {}).held();
        s.startRendering().submitHeld(kPolygon).endRendering();
    }
    // Groups: a display group holding a triangle inside an ordered group,
    // a cycle refused, both drawn, bounded by CalcAndUse, walked, removed
    // from while walked, duplicated; a push / pop pair met in the group.
    {
        Seed& s = add("groups");
        s.scene();
        s.surface(0, 0, {0, 0, 0, 1, 0, 0, 0, 1, 0});
        // groups(): the action, the group, then what the action reads.
        s.op(Op::kGroups).u8(0).held().u8(1);                     // display group (group 0)
        s.op(Op::kGroups).u8(0).held().u8(2);                     // ordered display group (group 1)
        s.op(Op::kGroups).u8(0).held().u8(6);                     // push (group 2)
        s.op(Op::kGroups).u8(0).held().u8(7);                     // pop (group 3)
        s.op(Op::kGroups).u8(1).held(0).u8(kGroup).held(2).u8(0).u8(0);   // add push
        s.op(Op::kGroups).u8(1).held(0).u8(kTriangle).held().u8(0).u8(0); // add the triangle
        s.op(Op::kGroups).u8(1).held(0).u8(kGroup).held(3).u8(0).u8(0);   // add pop
        s.op(Op::kGroups).u8(1).held(1).u8(kGroup).held(0).u8(0).u8(0);   // group 0 into group 1
        s.op(Op::kGroups).u8(1).held(1).u8(kTriangle).held().u8(0).u8(1); // triangle: before group 0
        s.op(Op::kGroups).u8(1).held(0).u8(kGroup).held(1).u8(0).u8(0);   // cycle: refused
        s.op(Op::kGroups).u8(1).held(0).u8(kGroup).held(0).u8(0).u8(0);   // itself: refused
        s.startRendering().op(Op::kGroups).u8(7).held(1).held().u8(1).endRendering();
        s.op(Op::kGroups).u8(8).held(1).held().u8(0);             // CalcAndUseBoundingBox
        s.op(Op::kGroups).u8(6).held(1).u8(1).value(0).value(0).value(0).value(0).value(0).value(0).u8(0);
        s.op(Op::kGroups).u8(4).held(1).u8(1);                    // walk and count geometry
        s.op(Op::kGroups).u8(9).held(0).u8(kTriangle).held().u8(1); // positions of the triangle
        s.op(Op::kDuplicate).u8(kGroup).held(1);
        s.op(Op::kGroups).u8(3).held(0).u8(1).u8(0);              // remove every other while walking
        s.op(Op::kGroups).u8(2).held(1).u8(0).u8(0).u8(kGroup).held(1).u8(0); // set: itself, refused
        s.op(Op::kGroups).u8(5).held(1).u8(1).u8(0).u8(0);        // empty all
    }
    // Every style, the illumination shaders and every light kind: made,
    // edited with good and bad values, submitted in a rendering loop.
    // stylesShadersLights(): action 0 style (which, value, state byte, data,
    // null byte, path: New / Submit to a view / Set on a held style), 1 type
    // and submit calls, 2 shaders, 3 light New or SetData, 4 light setter.
    {
        Seed& s = add("styles-shaders-lights");
        auto style = [&s](std::uint8_t which) -> Seed& { return s.op(Op::kStylesShadersLights).u8(0).u8(which); };
        auto tail = [&s](std::uint8_t path) -> Seed& {
            s.u8(1).u8(path);
            return path == 0 ? s : s.held();
        };
        // New: fill edges, backfacing remove, interpolation pixel,
        // orientation clockwise, cast shadows 5 (true), receive shadows 0.
        const std::uint8_t values[] = {1, 1, 2, 1, 2, 0};
        for (std::uint8_t which = 0; which < 6; ++which) {
            style(which).u8(values[which]).u8(0);
            tail(0);
        }
        style(6).u32(42).u8(0);
        tail(0);
        style(7).u8(5).u8(0); // pick parts face | vertex
        tail(0);
        style(8).u8(1).u8(3).value(0.5f); // anti-alias on, edges | filled
        tail(0);
        style(9).u8(1).u8(0).value(1).value(10).value(0.25f).value(1).value(1).value(0).value(0); // linear fog
        tail(0);
        style(10).u8(0).null(); // highlight without a set
        tail(0);
        // Bad values: fill 3, orientation -1, pick parts 8, quality NaN,
        // linear fog with start == end, a highlight set that is a style.
        style(0).u8(3).u8(0);
        tail(0);
        style(3).u8(224).u32(0xFFFFFFFF).u8(0);
        tail(0);
        style(7).u8(8).u8(0);
        tail(0);
        style(8).u8(1).u8(1).special(0);
        tail(0);
        style(9).u8(1).u8(0).value(5).value(5).value(1).value(1).value(1).value(1).value(1);
        tail(0);
        style(10).u8(0).held(0);
        tail(0);
        // Set on the first held style (the fill style): valid, then bad.
        style(0).u8(2).u8(0);
        tail(2);
        style(0).u8(224).u32(1000000).u8(0);
        tail(2);
        style(1).u8(1).u8(0); // a backfacing value to the fill style: wrong kind
        tail(2);
        // Shaders: Phong, Lambert, NULL; a uv transform, a NaN one, a bad boundary.
        for (std::uint8_t kind = 0; kind < 3; ++kind)
            s.op(Op::kStylesShadersLights).u8(2).u8(0).u8(kind);
        s.op(Op::kStylesShadersLights).u8(2).u8(1).held().u8(1);
        for (int i = 0; i < 9; ++i)
            s.u8(1).value(i % 4 == 0 ? 2.0f : 0.0f);
        s.u8(1);
        s.op(Op::kStylesShadersLights).u8(2).u8(1).held(1).u8(1);
        for (int i = 0; i < 9; ++i)
            (i == 4 ? s.u8(1).special(1) : s.u8(0));
        s.u8(1);
        s.op(Op::kStylesShadersLights).u8(2).u8(2).held().u8(1).u8(1).u8(1);  // v clamp
        s.op(Op::kStylesShadersLights).u8(2).u8(2).held().u8(1).u8(0).u8(2);  // u 2: bad
        s.op(Op::kStylesShadersLights).u8(2).u8(3).held().u8(1).u8(1);
        // Lights: each kind made with good values (a spot light with hot
        // 0.25 and outer 0.5), then one made with a zero direction. light()
        // writes the values up to the null byte; then come the light handle
        // and New / SetData (action 3) or the setter (action 4).
        auto light = [&s](std::uint8_t action, std::uint8_t kind, float hot, float outer, float dy) -> Seed& {
            s.op(Op::kStylesShadersLights).u8(action).u8(kind);
            s.u8(1).value(0.75f).value(1).value(0.5f).value(0.25f).u8(0).u8(1);
            s.value(0).value(5).value(0).value(0).value(dy).value(0).value(hot).value(outer).u8(3);
            return s.u8(1);
        };
        for (std::uint8_t kind = 0; kind < 4; ++kind)
            light(3, kind, 0.25f, 0.5f, -1).held().u8(1);
        light(3, 1, 0.25f, 0.5f, 0).held().u8(1);
        // SetData of the spot light with outer below hot; then its hot angle
        // set above its outer angle, the outer angle widened to 1.5, and a
        // NaN outer angle.
        light(3, 3, 0.5f, 0.25f, -1).held(3).u8(0);
        light(4, 3, 1, 1, -1).held(3).u8(13);
        light(4, 3, 1, 1.5f, -1).held(3).u8(14);
        light(4, 3, 1, kNaN, -1).held(3).u8(14);
        // Everything submitted in a rendering loop.
        s.scene().startRendering();
        s.op(Op::kStylesShadersLights).u8(1).u8(0).held().held().u8(1).u8(3);  // Q3Style_Submit
        s.op(Op::kStylesShadersLights).u8(1).u8(1).held().held().u8(1).u8(4);  // Q3Shader_Submit
        style(2).u8(0).u8(0);
        tail(1);
        style(9).u8(1).u8(2).value(0).value(0).value(0.5f).value(0).value(0).value(0).value(1);
        tail(1);
        s.submitHeld(kOtherStyle, 1, 1).submitHeld(kLight, 0, 1).endRendering();
        s.op(Op::kDuplicate).u8(kOtherStyle).held(10).op(Op::kDuplicate).u8(kLight).held(3);
    }
    // Every quadric and solid: made (a box with face sets), drawn, bounded,
    // decomposed under each subdivision method, edited field by field at the
    // edges (box face 5, 6 and ULONG_MAX, a NaN ratio, unknown caps bits),
    // and SetData with a NaN; three inputs, as each may draw 12 times.
    auto newQuadrics = [](Seed& s) -> Seed& {
        // quadrics(): type, action, non-null byte; New and SetData read the
        // described data.
        for (std::uint8_t type = 0; type < 7; ++type)
            s.op(Op::kQuadrics).u8(type).u8(0).u8(1).quadricData(type);
        return s;
    };
    {
        Seed& s = newQuadrics(add("quadrics-draw")).scene(2).startRendering();
        for (std::uint8_t kind = kBox; kind <= kTorus; ++kind)
            s.submitHeld(Kind(kind));
        s.endRendering().startBox();
        for (std::uint8_t kind = kBox; kind <= kEllipse; ++kind)
            s.submitHeld(Kind(kind));
        s.endBox();
    }
    {
        Seed& s = newQuadrics(add("quadrics-decompose")).scene(2);
        s.startRendering().submitStyle(kWorld, 0.2f);
        for (std::uint8_t type = 0; type < 7; ++type)
            s.op(Op::kQuadrics).u8(type).u8(5).u8(1).held().held();
        s.endRendering().startRendering().submitStyle(kScreen, 8.0f);
        for (std::uint8_t type = 1; type < 6; ++type)
            s.op(Op::kQuadrics).u8(type).u8(5).u8(1).held().held();
        s.endRendering();
    }
    {
        Seed& s = newQuadrics(add("quadrics-edits"));
        // quadricField(): the shape, null byte, set byte, field, slot, a
        // point, a ratio, caps, the set byte, a face index.
        auto field = [&s](std::uint8_t type, std::uint8_t which, std::uint8_t slot) -> Seed& {
            return s.op(Op::kQuadrics).u8(type).u8(4).u8(1).held().u8(1).u8(1).u8(which).u8(slot);
        };
        field(0, 2, 0).value(0).value(0).value(0).value(1).u8(0).u8(0).smallIndex(5);
        field(0, 2, 0).value(0).value(0).value(0).value(1).u8(0).u8(0).smallIndex(6);
        field(0, 2, 0).value(0).value(0).value(0).value(1).u8(0).u8(0).rawIndex(0xFFFFFFFFu);
        field(0, 1, 1).value(0).value(2).value(0).value(1).u8(0).u8(0).smallIndex(0);  // major = orientation
        field(1, 0, 0).special(0).value(0).value(0).value(1).u8(0).u8(0).smallIndex(0); // NaN origin
        field(1, 3, 0).value(0).value(0).value(0).value(1).u8(224).u32(0x100).u8(0).smallIndex(0);
        field(2, 3, 0).value(0).value(0).value(0).value(1).u8(3).u8(0).smallIndex(0);
        field(6, 3, 0).value(0).value(0).value(0).special(0).u8(0).u8(0).smallIndex(0);
        field(6, 3, 0).value(0).value(0).value(0).value(0.25f).u8(0).u8(0).smallIndex(0);
        field(3, 1, 2).value(0).value(0).value(3).value(1).u8(0).u8(0).smallIndex(0);
        // Cone SetData with a NaN vMax (float 15), then a partial torus (uMax).
        s.op(Op::kQuadrics).u8(1).u8(1).u8(1).quadricData(1, {{15, kNaN}}).held();
        s.op(Op::kQuadrics).u8(6).u8(1).u8(1).quadricData(6, {{14, 0.75f}}).held();
        s.scene(2).startRendering().submitHeld(kTorus).submitHeld(kCone).endRendering();
    }
    // Described data at its edges (FuzzInput.h): counts past
    // kQ3GeometryMaxArrayCount with a one-element decoy array or NULL, a
    // NULL vertex array, a polyline's segment sets, a stray vertex set (all
    // refused but the segment sets); a degenerate torus (ratio 0) kept,
    // drawn and decomposed to nothing.
    {
        Seed& s = add("described-data-edges");
        s.op(Op::kSurfaces).u8(1).u8(0).u8(1).null().u8(232).noSet().u8(0);        // limit + 1, decoy
        s.op(Op::kSurfaces).u8(1).u8(0).u8(1).null().u8(244).noSet().u8(1);        // ULONG_MAX, NULL
        s.op(Op::kNewOtherGeometry).u8(2).null().count(3).noSet().noArray().noArray(); // NULL vertices
        s.op(Op::kNewOtherGeometry).u8(2).null().count(2).noSet().array().vertex(0, 0, 0).vertex(1, 0, 0);
        s.array().noSet();                                                          // one segment set
        s.op(Op::kSurfaces).u8(0).u8(0).u8(1).null().vertex(0, 0, 0).xyz(1, 0, 0).u8(240).stray();
        s.vertex(0, 1, 0).noSet();                                                  // a stray set
        s.op(Op::kQuadrics).u8(6).u8(0).u8(1).quadricData(6, {{12, 0.0f}});        // torus, ratio 0
        s.scene(2).startRendering().submitHeld(kTorus).endRendering();
        s.startRendering().op(Op::kQuadrics).u8(6).u8(5).u8(1).held().held().endRendering();
    }
    // described(): each of its eight types made from valid described data
    // (FuzzInput.h), read back, set again, drawn and decomposed: a square
    // general polygon, an 8 x 2 marker bitmap, a 2 x 2 RGB32 pixmap in a
    // 16-byte memory storage, Listing 1's curve, a bilinear patch with a
    // square trim loop, a tetrahedron, a 2 x 3 grid, a TriMesh triangle with
    // vertex colours.
    {
        auto head = [](Seed& s, std::uint8_t type, std::uint8_t action) -> Seed& {
            return s.op(Op::kDescribed).u8(type).u8(action).u8(1).null();
        };
        auto word = [](Seed& s, std::uint32_t v) -> Seed& { return v < 16 ? s.u8(std::uint8_t(v)) : s.u8(224).u32(v); };
        const std::vector<std::function<void(Seed&)>> data = {
            [&](Seed& s) { // general polygon: one contour of four vertices, complex
                s.count(1).u8(0).noSet().array().count(4).array();
                s.vertex(0, 0, 0).vertex(1, 0, 0).vertex(1, 1, 0).vertex(0, 1, 0);
            },
            [&](Seed& s) { // marker: 8 x 2 pixels, rows of 1 byte, big-endian bits
                s.xyz(0, 0, 0).u8(0).u8(0);
                word(s, 8).u8(2).u8(1).u8(0).array().u8(5).u8(10);
                s.noSet();
            },
            [&](Seed& s) { // pixmap marker: 2 x 2 RGB32, rows of 8 bytes, 16 bytes of storage
                s.xyz(0, 0, 0).u8(0).u8(0).u8(2).u8(2).u8(8);
                word(s, 32).u8(0).u8(0).u8(0).u8(48 + 16);
                for (int i = 0; i < 16; ++i)
                    s.u8(std::uint8_t(i * 16));
                s.noSet();
            },
            [&](Seed& s) { // NURB curve: Listing 1
                s.u8(4).u8(4).noSet().array();
                s.value(0).value(0).value(0).value(1).value(1).value(1).value(0).value(1);
                s.value(2).value(0).value(0).value(1).value(3).value(1).value(0).value(1);
                s.array();
                for (float k : {0, 0, 0, 0, 1, 1, 1, 1})
                    s.value(k);
            },
            [&](Seed& s) { // NURB patch: bilinear, 2 x 2, a square trim loop of order 2
                s.u8(2).u8(2).u8(2).u8(2).u8(1).noSet().array();
                s.value(0).value(0).value(0).value(1).value(1).value(0).value(0).value(1);
                s.value(0).value(1).value(0).value(1).value(1).value(1).value(0).value(1);
                s.array().value(0).value(0).value(1).value(1).array().value(0).value(0).value(1).value(1);
                s.array().u8(1).array().u8(2).u8(5).array(); // one loop of one curve of 5 points
                const float uv[5][2] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.75f, 0.75f}, {0.25f, 0.75f}, {0.25f, 0.25f}};
                for (const auto& p : uv)
                    s.value(p[0]).value(p[1]).value(1);
                s.array();
                for (float k : {0, 0, 1, 2, 3, 4, 4})
                    s.value(k);
            },
            [&](Seed& s) { // polyhedron: a tetrahedron, every side an edge
                s.count(4).u8(0).count(4).noSet().array();
                s.vertex(0, 0, 0).vertex(1, 0, 0).vertex(0, 1, 0).vertex(0, 0, 1).noArray().array();
                const std::uint8_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
                for (const auto& f : faces)
                    s.u8(f[0]).u8(f[1]).u8(f[2]).u8(7).noSet();
            },
            [&](Seed& s) { // triangle grid: 2 rows of 3, no facet sets
                s.count(2).count(3).noSet().array();
                for (int i = 0; i < 6; ++i)
                    s.vertex(float(i % 3), float(i / 3), 0);
                s.noArray();
            },
            [&](Seed& s) { // TriMesh: one triangle, its vertices' diffuse colours
                s.noSet().u8(1).count(0).u8(0).count(0).u8(3).count(1);
                s.xyz(0, 0, 0).xyz(1, 1, 0).u8(0);                   // bBox (Q3 computes its own)
                s.array().u8(0).u8(1).u8(2).array().noArray().array(); // triangles, no attributes, no edges
                s.array().u8(5).array(); // vertex colours (kQ3AttributeTypeDiffuseColor)
                s.xyz(1, 0, 0).xyz(0, 1, 0).xyz(0, 0, 1).u8(0);
                s.array().xyz(0, 0, 0).xyz(1, 0, 0).xyz(0, 1, 0);
            },
        };
        static const Kind kKinds[] = {kGeneralPolygon, kMarker, kPixmapMarker, kCurve, kPatch, kPolyhedron, kTriGrid, kTriMesh};
        static const char* const kNames[] = {"described-general-polygon", "described-marker", "described-pixmap-marker",
                                             "described-curve", "described-patch", "described-polyhedron",
                                             "described-trigrid", "described-trimesh"};
        for (std::uint8_t type = 0; type < 8; ++type) {
            Seed& s = add(kNames[type]);
            data[type](head(s, type, 0));
            data[type](head(s, type, 1));
            s.held();
            data[type](head(s, type, 2));
            s.held();
            s.scene(2).startRendering().submitHeld(kKinds[type]).endRendering().decompose();
        }
    }
    // A mesh: a square with a square hole (FaceToContour) and a triangle on
    // its right edge, walked, checked against its counts, drawn, bounded,
    // decomposed, edited with a deleted face, a made-up handle and a NaN
    // point, taken apart, and duplicated.
    {
        Seed& s = add("meshes");
        s.op(Op::kMeshes).u8(0);
        const float xy[9][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {6, 2}};
        for (const auto& p : xy)
            s.op(Op::kMeshes).u8(1).held().value(p[0] / 4).value(p[1] / 4).value(0).u8(0).u8(1);
        // meshes() FaceNew: size - 3, source, vertex picks (the mesh's own, in
        // order), the count byte, the set byte. Parts: vertices 0-8.
        s.op(Op::kMeshes).u8(2).held().u8(1).u8(0).u8(0).u8(1).u8(2).u8(3).u8(1).u8(0);     // part 9
        s.op(Op::kMeshes).u8(2).held().u8(1).u8(0).u8(4).u8(5).u8(6).u8(7).u8(1).u8(0);     // part 10
        s.op(Op::kMeshes).u8(2).held().u8(0).u8(0).u8(1).u8(8).u8(2).u8(1).u8(0);           // part 11
        s.op(Op::kMeshes).u8(4).held().u8(0).u8(9).u8(0).u8(10).u8(1);                      // hole: part 12
        for (std::uint8_t walk = 0; walk < 13; ++walk)
            s.op(Op::kMeshes).u8(6).held().u8(0).u8(walk < 2 ? 0 : walk < 5 ? 1 : walk < 9 ? 9 : 12).u8(walk);
        s.op(Op::kMeshes).u8(7).held();
        s.op(Op::kMeshes).u8(5).held().u8(0).u8(2).u8(0).u8(3).u8(0).u8(9);                 // a corner set
        s.scene(2).startRendering().submitHeld(kMesh).endRendering().startBox().submitHeld(kMesh).endBox();
        s.decompose();
        s.op(Op::kMeshes).u8(3).held().u8(0).u8(11).u8(0);                                  // delete the triangle
        s.op(Op::kMeshes).u8(3).held().u8(0).u8(11).u8(0);                                  // and again
        s.op(Op::kMeshes).u8(5).held().u8(230).u32(0x12345679).u8(0).u8(0);                // a made-up vertex
        s.op(Op::kMeshes).u8(5).held().u8(0).u8(3).u8(0).u8(4).special(0).value(0).value(0); // a NaN point
        s.op(Op::kMeshes).u8(4).held().u8(0).u8(12).u8(0);                                  // the hole back out
        s.op(Op::kMeshes).u8(7).held();
        s.op(Op::kDuplicate).u8(kMesh).held();
        s.op(Op::kMeshes).u8(3).held().u8(0).u8(2).u8(1);                                   // delete vertex 2
        s.op(Op::kMeshes).u8(7).held();
    }
    // NURB patches (patches(): the action byte, then readPatch()'s bytes:
    // flags, orders, extra columns and rows, shape, scale, overwrites, trim
    // loops, the huge-curve-count byte of each loop, the non-null byte).
    struct Loop {
        std::uint8_t flags, curves, u, v, radius, order;
    };
    auto newPatch = [](Seed& s, std::uint8_t flags, std::uint8_t uOrder, std::uint8_t vOrder, std::uint8_t shape,
                       const std::vector<Loop>& loops) -> Seed& {
        s.op(Op::kPatches).u8(0).u8(flags);
        if (flags & 1)
            s.u32(uOrder == 0 ? 0xFFFFFFFFu : uOrder);
        else
            s.u8(std::uint8_t(uOrder - 1));
        if (flags & 2)
            s.u32(vOrder == 0 ? 0xFFFFFFFFu : vOrder);
        else
            s.u8(std::uint8_t(vOrder - 1));
        s.u8(2).u8(3).u8(shape).value(2.0f).u8(0).u8(std::uint8_t(loops.size()));
        for (const Loop& l : loops) {
            s.u8(l.flags).u8(l.curves).u8(l.u).u8(l.v).u8(l.radius);
            for (std::uint8_t k = 0; k < l.curves; ++k) {
                if (l.flags & 2)
                    s.u32(l.order == 0 ? 0xFFFFFFFFu : l.order);
                else
                    s.u8(std::uint8_t(l.order - 1));
                s.u8(1);
            }
        }
        for (std::size_t l = 0; l < loops.size(); ++l)
            s.u8(0);
        if (flags & 8)
            s.u8(0);
        if (flags & 16)
            s.u8(1);
        if (flags & 4)
            s.u8(0);
        if (flags & 32)
            s.held();
        return s.u8(1);
    };
    // A plain rational bicubic; a quadratic-by-quartic one with an outer
    // loop of two curves, a hole and an island in it; both drawn, bounded
    // and decomposed under each method.
    auto twoPatches = [&](Seed& s) -> Seed& {
        newPatch(s, 0, 4, 4, 1, {});
        return newPatch(s, 0, 3, 5, 2 | 4, {{0, 2, 128, 128, 250, 3}, {1, 1, 128, 128, 120, 4}, {0, 1, 128, 128, 50, 2}});
    };
    {
        Seed& s = twoPatches(add("patches-draw")).scene(2);
        s.startRendering().submitHeld(kPatch, 0).submitHeld(kPatch, 1).endRendering();
        s.startBox().submitHeld(kPatch, 1).endBox();
        s.startRendering().submitStyle(kWorld, 0.3f);
        s.op(Op::kPatches).u8(5).held(0).held().op(Op::kPatches).u8(5).held(1).held();
        s.endRendering().startRendering().submitStyle(kScreen, 6.0f);
        s.op(Op::kPatches).u8(5).held(1).held().op(Op::kPatches).u8(6).held(0).held();
        s.endRendering().startRendering().submitStyle(kConstant, 3.0f).decompose(0).endRendering();
    }
    // Bad data: an order of ULONG_MAX, huge counts, NULL arrays, an open
    // loop, a loop with no curves, a NaN weight, then SetData of the same.
    {
        Seed& s = twoPatches(add("patches-bad"));
        newPatch(s, 1, 0, 4, 0, {});
        newPatch(s, 8 | 16, 4, 4, 0, {});
        newPatch(s, 4, 2, 2, 0, {{0, 1, 128, 128, 100, 3}});
        newPatch(s, 64 | 128, 4, 4, 0, {});
        newPatch(s, 0, 4, 4, 0, {{16, 2, 100, 100, 100, 3}});
        newPatch(s, 0, 4, 4, 0, {{0, 0, 100, 100, 100, 3}});
        newPatch(s, 0, 4, 4, 0, {{2, 1, 100, 100, 100, 0}});
        // A NaN weight (component 3 of point 5), then a decreasing knot.
        s.op(Op::kPatches).u8(0).u8(0).u8(3).u8(3).u8(0).u8(0).u8(0).value(1.0f).u8(2);
        s.u8(0xC0).special(0).u16(5).u8(1).value(-5.0f).u16(6).u8(0).u8(1);
        s.op(Op::kPatches).u8(1).u8(0).u8(3).u8(3).u8(0).u8(0).u8(0).value(1.0f).u8(1);
        s.u8(0xC0).special(0).u16(5).u8(0).u8(1).held();
        s.scene().startRendering().submitHeld(kPatch, 1).endRendering();
    }
    // Every per-field call at the edges of its indices (patchField(): the
    // patch, field byte, null byte, row, column, u knot and v knot indices,
    // a point, a knot).
    {
        Seed& s = twoPatches(add("patches-edits"));
        auto field = [&s](std::uint8_t which, std::uint8_t row, std::uint8_t knot) -> Seed& {
            s.op(Op::kPatches).u8(4).held(1).u8(which).u8(1).smallIndex(row).smallIndex(1).smallIndex(knot);
            return s.smallIndex(knot).value(0.5f).value(0.5f).value(0.5f).value(1.0f).value(0.5f);
        };
        for (std::uint8_t which = 0; which < 6; ++which) {
            field(which, 0, 0);
            field(which, 6, 12);
            field(which, 7, 13);
        }
        s.op(Op::kPatches).u8(4).held(1).u8(1).u8(1).rawIndex(0xFFFFFFFFu).smallIndex(0).smallIndex(0);
        s.smallIndex(0).special(0).value(0).value(0).value(1).value(0);
        s.op(Op::kPatches).u8(2).u8(0).u8(3).u8(3).u8(0).u8(0).u8(0).value(1).u8(0).u8(0).u8(0);
        s.op(Op::kDuplicate).u8(kPatch).held(1);
        s.scene(2).startRendering().submitHeld(kPatch, 2).endRendering().dispose(kPatch, 1);
    }
    // polygons2(): one general polygon (a square with a square hole), a
    // polyhedron (two triangles), a 2 x 3 triangle grid and a marker (an
    // 8 x 8 frame), made with New, drawn, bounded and edited.
    {
        Seed& s = add("polygons2");
        auto vertex = [&s](std::uint8_t x, std::uint8_t y) { s.u8(x).u8(y).u8(1); };
        // type, action (New), not null, the vertex count byte.
        s.op(Op::kPolygons2).u8(0).u8(0).u8(1).u8(6);
        for (const auto& p : {std::pair<int, int>{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {4, 4}, {2, 4}})
            vertex(std::uint8_t(p.first), std::uint8_t(p.second));
        s.u8(0).u8(1).u8(3).u8(3).u8(1); // no z, no raw count, contours of 4 and 4, concave
        s.op(Op::kPolygons2).u8(1).u8(0).u8(1).u8(2);
        for (const auto& p : {std::pair<int, int>{0, 0}, {6, 0}, {0, 6}, {3, 3}})
            vertex(std::uint8_t(p.first), std::uint8_t(p.second));
        s.u8(0).u8(1).u8(1); // no z, no raw count, two triangles
        for (const auto& t : {std::pair<int, int>{0, 1}, {1, 3}}) {
            for (int k : {t.first, t.second, 2})
                s.u8(1).u8(3).u8(std::uint8_t(k));
            s.u8(7).u8(1); // all edges, no set
        }
        s.u8(0); // no edges
        s.op(Op::kPolygons2).u8(2).u8(0).u8(1).u8(4);
        for (const auto& p : {std::pair<int, int>{0, 0}, {3, 0}, {6, 0}, {0, 3}, {3, 3}, {6, 3}})
            vertex(std::uint8_t(p.first), std::uint8_t(p.second));
        s.u8(0).u8(1).u8(2); // no z, no raw count, three columns
        for (int f = 0; f < 12; ++f)
            s.u8(1);
        s.u8(0); // no facet sets
        s.op(Op::kPolygons2).u8(3).u8(0).u8(1).u8(0);
        vertex(0, 0);
        vertex(1, 1);
        s.u8(0).u8(1).u8(7); // no z, no raw count, 8 bytes of bits
        for (std::uint8_t b : {0xFF, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xFF})
            s.u8(b);
        s.u8(0xFC).u8(0xFF).u8(0xFF).u8(0xFF).u8(0xFC).u8(0).u8(8).u8(0); // x -4, y -4, rowBytes 1, width 8, big
        s.scene(2).startRendering();
        for (Kind kind : {kGeneralPolygon, kPolyhedron, kTriGrid, kMarker})
            s.submitHeld(kind);
        s.endRendering().startBox();
        for (Kind kind : {kGeneralPolygon, kPolyhedron, kTriGrid, kMarker})
            s.submitHeld(kind);
        s.endBox();
        // Per-field edits: a vertex moved, a facet set at the last index,
        // a marker offset; then a shape hint read.
        // polygons2Field(): the shape, null byte, call, i and j (a selector
        // byte and a byte each), a point, the set byte.
        auto field = [&s](std::uint8_t type, std::uint8_t call, std::uint8_t i, std::uint8_t j) -> Seed& {
            return s.op(Op::kPolygons2).u8(type).u8(4).u8(1).held().u8(1).u8(call).u8(1).u8(i).u8(1).u8(j);
        };
        field(0, 1, 1, 2).value(1).value(1).value(0).u8(0);
        field(2, 5, 3, 0).value(0).value(0).value(0).u8(1);
        field(3, 3, 0, 5).value(0).value(0).value(0).u8(0);
        field(1, 5, 1, 3).value(0).value(0).value(0).u8(0);
        field(0, 4, 0, 0).value(0).value(0).value(0).u8(0);
        s.scene(2).startRendering().submitHeld(kMarker).submitHeld(kGeneralPolygon).endRendering();
    }
    // pixmapMarkers(): a 4 x 3 pixmap marker of every pixel type (byte
    // orders alternating), drawn, bounded and edited; then bad pixmaps: a
    // raw pixel type, a huge width, a wrong pixel size, a storage a byte
    // short, an image that is not a storage, a NULL image.
    {
        Seed& s = add("pixmap-markers");
        // storagePixmap(): flags, type (enumValue), width, height, row
        // padding, byte and bit orders, then (flags bits 4-5 zero) the first
        // 16 bytes of the storage.
        auto pixmap = [&s](std::uint8_t flags, std::uint8_t type, std::uint8_t order) -> Seed& {
            s.u8(flags).u8(type).u8(4).u8(3).u8(1).u8(order).u8(0);
            if ((flags & 0x30) == 0)
                for (int i = 0; i < 16; ++i)
                    s.u8(std::uint8_t(0x30 + 13 * i));
            return s;
        };
        // The rest of pixmapMarkers(): position, x and y offsets, no set.
        auto tail = [&s](float x) { s.value(x).value(0.5f).value(0).u32(0xFFFFFFFE).u8(0xFE).u8(0); };
        for (std::uint8_t type = 0; type < 6; ++type) {
            s.op(Op::kPixmapMarkers).u8(0).u8(1);
            pixmap(0, type, type % 2);
            tail(float(type) / 2);
        }
        s.scene(0).startRendering();
        for (std::uint8_t i = 0; i < 6; ++i)
            s.submitHeld(kPixmapMarker, i);
        s.endRendering().startBox();
        for (std::uint8_t i = 0; i < 6; ++i)
            s.submitHeld(kPixmapMarker, i);
        s.endBox();
        // Immediate mode inside a loop, then SetData and GetData.
        s.startRendering().op(Op::kPixmapMarkers).u8(3).u8(1);
        pixmap(0, 1, 1);
        tail(1);
        s.held().endRendering();
        s.op(Op::kPixmapMarkers).u8(1).u8(1);
        pixmap(0, 5, 0);
        tail(2);
        s.held(2);
        s.op(Op::kPixmapMarkers).u8(2).u8(1);
        pixmap(0, 0, 0);
        tail(0);
        s.held(3);
        // Bad pixmaps for New: raw type 7, huge width, pixel size 8, a byte
        // short, an attribute set, NULL.
        s.op(Op::kPixmapMarkers).u8(0).u8(1).u8(0).u8(0xE0).u32(7).u8(4).u8(3).u8(1).u8(0).u8(0);
        for (int i = 0; i < 16; ++i)
            s.u8(0xFF);
        tail(0);
        s.op(Op::kPixmapMarkers).u8(0).u8(1).u8(1).u8(1).u32(0xFFFFFFFF).u8(3).u8(1).u8(0).u8(0);
        for (int i = 0; i < 16; ++i)
            s.u8(0x11);
        tail(0);
        s.op(Op::kPixmapMarkers).u8(0).u8(1).u8(8).u8(1).u8(4).u8(3).u8(1).u8(8).u8(0).u8(0);
        for (int i = 0; i < 16; ++i)
            s.u8(0xFF);
        tail(0);
        s.op(Op::kPixmapMarkers).u8(0).u8(1);
        pixmap(0x40, 3, 1);
        tail(0);
        s.op(Op::kPixmapMarkers).u8(0).u8(1);
        pixmap(0x10, 1, 0).held();
        tail(0);
        s.op(Op::kPixmapMarkers).u8(0).u8(1);
        pixmap(0x20, 1, 0);
        tail(0);
        // pixmapMarkerField(): the marker, null byte, call, its arguments.
        auto field = [&s](std::uint8_t which, std::uint8_t call) -> Seed& {
            return s.op(Op::kPixmapMarkers).u8(4).u8(1).held(which).u8(1).u8(call);
        };
        field(0, 0);
        field(0, 1).value(1).value(1).value(0);
        field(1, 2);
        field(1, 3).u32(0x80000000);
        field(2, 4).u8(1);
        field(3, 5);
        field(4, 6);
        pixmap(0, 4, 1);
        field(4, 6).u8(8).u8(4).u8(4).u8(3).u8(1).u8(24).u8(1).u8(0); // pixel size 24 for RGB16_565
        for (int i = 0; i < 16; ++i)
            s.u8(0x22);
        field(5, 7);
        s.op(Op::kDuplicate).u8(kPixmapMarker).held(0);
        s.scene(2).startRendering().submitHeld(kPixmapMarker, 0).submitHeld(kPixmapMarker, 6).endRendering();
        s.decompose(0).dispose(kPixmapMarker, 0);
    }
    // Q3Exit while objects live, calls while not initialized, nesting.
    {
        Seed& s = add("initialize-exit");
        s.newCurveListing1().op(Op::kInitializeExit).u8(1).op(Op::kInitializeExit).u8(0);
        s.op(Op::kInitializeExit).u8(0).op(Op::kInitializeExit).u8(0);
        s.op(Op::kSetKnot).held().smallIndex(0).value(0).dispose(kCurve);
        s.op(Op::kNewStyle).u8(0).value(1).value(1).op(Op::kInitializeExit).u8(1);
        s.op(Op::kSetKnot).held().smallIndex(0).value(0);
    }
    // Raw curves: every value from the input.
    {
        Seed& s = add("raw-curves");
        s.op(Op::kNewCurve).rawCurve(2, {0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1}, 0, {0, 0, 1, 1, 0});
        s.op(Op::kNewCurve).rawCurve(3, {0, 0, 0, 1, 1, 2, 0, 1, 2, 0, 0, 1}, 0, {0, 0, 1, 0, 0, 0});
        s.scene().startRendering().submitHeld(kCurve, 0).submitHeld(kCurve, 1).endRendering();
        s.op(Op::kNewCurve).generatedCurve(5, 40, 2.0f, 1 | 2 | 4 | 16);
        s.startBox(1).submitHeld(kCurve, 2).endBox();
    }
    {
        Seed& s = add("curve-raw-order");
        s.op(Op::kNewCurve).u8(q3fuzz::kCurveListing1 | q3fuzz::kCurveRawOrder).u32(0xFFFFFFFF).u8(0);
        s.op(Op::kNewCurve).u8(q3fuzz::kCurveGenerated | q3fuzz::kCurveRawOrder).u32(16).u16(100);
        s.value(1).u8(2).u8(0);
        s.op(Op::kNewCurve).u8(q3fuzz::kCurveGenerated | q3fuzz::kCurveRawOrder).u32(0).u16(3).value(1).u8(0).u8(0);
    }
    // Screen-space subdivision with c1 under a pixel on a large pane.
    {
        Seed& s = add("screen-space-fine");
        s.scene(2).op(Op::kNewCurve).generatedCurve(4, 300, 1.0f, 2 | 4);
        s.startRendering().submitStyle(kScreen, 0.01f).submitHeld(kCurve).decompose().endRendering();
        s.startRendering().submitStyle(kConstant, 3).submitHeld(kCurve).endRendering();
    }
    // One retained curve drawn by two views, then edited between frames.
    {
        Seed& s = add("two-views-one-curve");
        s.scene().scene(2).newCurveListing1();
        s.op(Op::kStartRendering).held(0).op(Op::kStartRendering).held(1);
        s.op(Op::kSubmitRetained).u8(kCurve).held().held(0).u8(0);
        s.op(Op::kSubmitRetained).u8(kCurve).held().held(1).u8(1);
        s.op(Op::kEndRendering).held(1).op(Op::kEndRendering).held(0);
        s.op(Op::kSetKnot).held().smallIndex(7).value(2);
        s.op(Op::kStartRendering).held(1).op(Op::kSubmitRetained).u8(kCurve).held().held(1).u8(0);
        s.op(Op::kEndRendering).held(1);
    }
    // Immediate-mode submits of bad curve data inside a loop.
    {
        Seed& s = add("immediate-bad-curves");
        s.scene().startRendering();
        s.op(Op::kSubmitCurveImmediate).listing1Curve({{1, kNaN, 2}}).held().u8(1);
        s.op(Op::kSubmitCurveImmediate).listing1Curve({}, q3fuzz::kCurveNullKnots).held().u8(1);
        s.op(Op::kSubmitCurveImmediate).listing1Curve({}, q3fuzz::kCurveHugeCount).held().u8(1);
        s.op(Op::kSubmitCurveImmediate).listing1Curve().held().u8(0);
        s.op(Op::kSubmitCurveImmediate).listing1Curve().stray().u8(1);
        s.endRendering();
    }
    // viewHints(): hints from a scene's view, every Set and Get with good
    // objects, then the wrong kinds, NULL, huge dimensions, bad bitmaps, a
    // raw clear method and non-finite colours.
    {
        Seed& s = add("view-hints");
        s.scene(2);
        s.op(Op::kViewHints).u8(0).held();
        s.op(Op::kViewHints).u8(1).held().u8(1).held();
        s.op(Op::kViewHints).u8(2).held().u8(1).held();
        s.op(Op::kViewHints).u8(4).held().u8(1).anyHeld(0);
        s.op(Op::kViewHints).u8(5).held().u8(1);
        s.op(Op::kViewHints).u8(6).held().u8(1).u8(0).u32(640).u32(480);
        s.op(Op::kViewHints).u8(6).held().u8(1).u8(32).u32(2).u32(480);
        s.op(Op::kViewHints).u8(7).held().u8(1).u8(1).u8(1);
        s.op(Op::kViewHints).u8(9).held().u8(1).u8(12).u8(3).u8(0).u8(0);
        s.op(Op::kViewHints).u8(9).held().u8(1).u8(12).u8(3).u8(0).u8(0xE0).u32(9);
        s.op(Op::kViewHints).u8(9).held().u8(0).u8(8).u8(2).u8(1).u8(1);
        s.op(Op::kViewHints).u8(8).held().u8(1);
        s.op(Op::kViewHints).u8(8).held().u8(0);
        s.op(Op::kViewHints).u8(10).held().u8(1).u8(1);
        s.op(Op::kViewHints).u8(10).held().u8(1).u8(0xF0).u32(0x80000000u);
        s.op(Op::kViewHints).u8(11).held().u8(1).value(1).value(0.5f).value(0.25f).value(0);
        s.op(Op::kViewHints).u8(11).held().u8(1).special(0).value(0).value(0).value(0);
        s.op(Op::kViewHints).u8(1).anyHeld(1).u8(1).held();
        s.op(Op::kViewHints).u8(3).held().u8(1).anyHeld(2);
        s.op(Op::kViewHints).u8(1).stray().u8(1).held();
        s.op(Op::kViewHints).u8(0).anyHeld(0);
        s.op(Op::kDuplicate).u8(kViewHints).held();
        s.dispose(kViewHints);
    }
    // picking(): a world-ray, a window-point and a window-rect pick, each run
    // in a picking loop over a point and a line, every detail of the first
    // hit read; then the getters, bad Sets (NaN tolerance, inverted rect,
    // zero ray), an end without a start and a stray handle.
    {
        Seed& s = add("picking");
        s.scene();
        s.newPoint(0, 0, 0).newLine(-1, 0, 0, 1, 0, 0);
        s.op(Op::kPicking).u8(0).u8(1).u8(1).u8(0).u32(0x3FF).u8(0).u8(2);
        s.value(0).value(0).value(5).value(0).value(0).value(-1).value(0.5f).value(0.5f);
        s.op(Op::kPicking).u8(0).u8(1).u8(1).u8(0).u32(0x3FF).u8(0).u8(0).value(32).value(32).value(1000).value(1000);
        s.op(Op::kPicking).u8(0).u8(1).u8(2).u8(0).u32(0x3FF).u8(1).u8(1).value(0).value(0).value(1000).value(1000);
        for (std::uint8_t w = 0; w < 3; ++w) {
            s.op(Op::kPicking).u8(3).u8(1).held(w).held();
            s.submitHeld(kPoint).submitHeld(kLine);
            s.op(Op::kPicking).u8(4).u8(1).held(w).held();
            for (std::uint8_t bit = 0; bit < 10; ++bit)
                s.op(Op::kPicking).u8(5).u8(1).held(w).u32(0).u8(0).u8(0).u8(bit);
            s.op(Op::kPicking).u8(5).u8(1).held(w).u32(0xFFFFFFFFu).u8(255).u8(0).u8(0);
        }
        s.op(Op::kPicking).u8(2).u8(1).held(0).op(Op::kPicking).u8(2).u8(0).held(1);
        s.op(Op::kPicking).u8(1).u8(1).held(0).special(0).u8(0);
        s.op(Op::kPicking).u8(1).u8(1).held(1).value(1).u8(2).value(2);
        s.op(Op::kPicking).u8(1).u8(1).held(2).value(5).u8(3).value(0).value(1).value(1);
        s.op(Op::kPicking).u8(1).u8(1).held(0).value(0).u8(4).value(0).value(0).value(0).value(0).value(0);
        s.op(Op::kPicking).u8(1).u8(1).held(0).value(0).u8(5).u8(9).u8(0).u32(1).u8(1);
        s.op(Op::kPicking).u8(6).u8(0).held(0).op(Op::kPicking).u8(7).u8(1).stray();
        s.op(Op::kPicking).u8(4).u8(1).held(0).held();
        s.dispose(kPick);
    }
    // controllers(): a controller made and activated, every call once on it
    // and its step's tracker (thresholds, buttons, positions, events), the
    // cursor tracker, then deactivation and decommission, a refused count and
    // an unknown controller pointer.
    {
        Seed& s = add("controllers");
        auto head = [&](std::uint8_t call, std::uint8_t choose) -> Seed& {
            s.op(Op::kControllers).u8(call).u8(1);
            if (choose != 0xFF)
                s.u8(choose).u8(0);
            s.u8(1).value(1).value(2).value(3).value(0.5f).value(0).value(0);
            s.value(0.7071f).value(0).value(0.7071f).value(0);
            return s.u32(3);
        };
        head(0, 0xFF).u8(0).u8(1).u8(1).u8(1);
        head(2, 1).u8(1).u8(1);
        head(1, 1).u8(0);
        head(3, 1).u8(16).u32(4).u8(1).u8(1);
        head(4, 1).u8(0).u32(5);
        head(5, 1);
        head(6, 1).value(1).value(2).value(3).u8(3).u8(0).u8(3).u8(0);
        head(7, 1);
        head(8, 1).value(0.5f).value(0.25f).u8(1).u8(0).u32(3).u32(1);
        head(9, 1).u8(0).u8(0).u8(0);
        head(10, 1).u8(3).u32(100).u32(1).u8(0).u32(200).u32(2).u8(3).u32(300).u32(4).u8(1).u32(190);
        head(11, 1).u8(0).u8(1).u8(0);
        head(12, 1).u8(1);
        head(2, 1).u8(0).u8(0);
        head(0, 1).u8(0).u8(4).u8(4).u8(1);
        s.op(Op::kControllers).u8(1).u8(1).u8(0).u8(0);
        s.value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).value(0).u32(0).u8(1);
    }
    // The curve tools (Q3NURBCurveTools.h) on a retained curve and on data: every
    // call once with good arguments, then NaN, a parameter outside the domain, an
    // index past the end and a count past the limit.
    {
        Seed& s = add("curve-tools");
        s.newCurveListing1();
        s.curveTool(true, 0, 0, 0, 0, 0, 0).curveTool(true, 1, 0.5f, 0, 0, 0, 0);
        s.curveTool(true, 2, 0.25f, 0, 0, 0, 0).curveTool(true, 3, 0.75f, 0, 0, 0, 0);
        s.curveTool(true, 4, 0.5f, 0, 0, 0, 0).curveTool(true, 5, 0.5f, 0, 0, 0, 2);
        s.curveTool(true, 6, 0, 0, 0, 0, 0, {0.25f, 0.75f, 0.5f}).curveTool(true, 7, 0, 0, 0.01f, 4, 1);
        s.curveTool(true, 8, 0, 0, 0, 0, 3).curveTool(true, 9, 0, 0, 0, 0, 0);
        s.curveTool(true, 10, 0, 0, 0, 0, 0).curveTool(true, 11, 0.5f, 0, 0, 0, 0);
        s.curveTool(true, 12, 0, 1, 0.001f, 0, 0).curveTool(true, 13, 0, 1.5f, 0.001f, 0, 0);
        s.curveTool(true, 14, 0, 0, 0, 0, 0);
        const std::vector<float> zigzag{0, 0, 0, 1, 2, 0, 2, 0, 0, 3, 2, 0, 4, 0, 1, 5, 2, 0};
        s.curveTool(false, 15, 0, 0, 0, 0, 0, {}, zigzag).curveTool(false, 16, 0, 0, 0, 0, 5, {}, zigzag);
        s.curveTool(false, 1, kNaN, 0, 0, 0, 0).curveTool(false, 5, 1.0f, 0, 0, 0, 1);
        s.curveTool(false, 10, 0, 0, 0, 9, 0).curveTool(false, 12, 0, 1, -1.0f, 0, 0);
        s.curveTool(false, 8, 0, 0, 0, 0, 13).curveTool(false, 12, 0, 0.9f, 1e-30f, 0, 0);
    }
    // portable(): each of its sixteen families once, with a scene's view
    // and draw context held (the kind byte, pick's two bytes, the type's
    // two, then the family; what follows reads as zeros).
    static const char* const kPortableNames[16] = {
        "portable-00", "portable-01", "portable-02", "portable-03", "portable-04", "portable-05",
        "portable-06", "portable-07", "portable-08", "portable-09", "portable-10", "portable-11",
        "portable-12", "portable-13", "portable-14", "portable-15"};
    for (std::uint8_t family = 0; family < 16; ++family) {
        Seed& s = add(kPortableNames[family]);
        s.scene();
        s.op(Op::kPortable).u8(kView).u8(0).u8(0).u8(0).u8(0).u8(family);
    }
    return all;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s DIRECTORY\n", argv[0]);
        return 2;
    }
    for (const auto& [name, seed] : seeds()) {
        const std::string path = std::string(argv[1]) + "/" + name;
        std::FILE* file = std::fopen(path.c_str(), "wb");
        if (file == nullptr) {
            std::perror(path.c_str());
            return 1;
        }
        const std::vector<std::uint8_t>& bytes = seed.bytes();
        const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
        if (std::fclose(file) != 0 || !ok) {
            std::perror(path.c_str());
            return 1;
        }
    }
    return 0;
}

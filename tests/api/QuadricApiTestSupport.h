// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the API tests of the quadrics and solids (BoxApiTest.cpp,
// ConeApiTest.cpp, ...) check for every type, written once: each type's file
// describes its calls and fields in a Shape (the functions, the vectors, the
// part attribute sets, the u/v parameters, a valid sample) and expands
// Q3_QUADRIC_API_TESTS(Fixture) into the common tests, then adds its own.
// What every geometry with a data structure owes (NULL and bad handles, NULL
// data, non-finite values, GetData/EmptyData references, Duplicate's
// sharing) is the contract suite's, GeometryContractTest.cpp; these tests
// hold what the quadrics add: their field-by-field calls, degenerate shapes,
// parameter ranges, part sets, bounds and decomposition. Every check calls
// only Q3* functions.

#include "OwningApiTest.h"
#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace q3test {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
inline const float kNonFinite[] = {kNaN, kInf, -kInf};

/// A vector of the data with Apple's Set/Get calls.
template <class Data> struct VectorAccess {
    const char* name;
    TQ3Vector3D Data::*member;
    TQ3Status (*set)(TQ3GeometryObject, const TQ3Vector3D*);
    TQ3Status (*get)(TQ3GeometryObject, TQ3Vector3D*);
};

/// A part attribute set of the data, with its Set/Get calls where Apple
/// declares them (null where only the data holds it).
template <class Data> struct SetAccess {
    const char* name;
    TQ3AttributeSet Data::*member;
    TQ3Status (*set)(TQ3GeometryObject, TQ3AttributeSet);
    TQ3Status (*get)(TQ3GeometryObject, TQ3AttributeSet*);
};

/// A float of the data (a coordinate, a parameter, the ratio).
template <class Data> struct FloatField {
    std::string name;
    std::function<float&(Data&)> at;
};

/// One QuickDraw 3D quadric or solid type, as its tests see it.
template <class Data> struct Shape {
    const char* name; ///< "cone", for messages
    TQ3ObjectType type;
    TQ3GeometryObject (*create)(const Data*);
    TQ3Status (*submit)(const Data*, TQ3ViewObject);
    TQ3Status (*setData)(TQ3GeometryObject, const Data*);
    TQ3Status (*getData)(TQ3GeometryObject, Data*);
    TQ3Status (*emptyData)(Data*);
    TQ3Status (*setOrigin)(TQ3GeometryObject, const TQ3Point3D*);
    TQ3Status (*getOrigin)(TQ3GeometryObject, TQ3Point3D*);
    TQ3Point3D Data::*origin;
    std::vector<VectorAccess<Data>> vectors; ///< the frame: must stay independent
    std::vector<SetAccess<Data>> sets;       ///< the part sets and the shape's own set
    TQ3AttributeSet Data::*own;
    std::vector<std::pair<const char*, float Data::*>> parameters; ///< u and v limits, in [0, 1]
    std::vector<FloatField<Data>> extraFloats;                     ///< others (the torus's ratio)
    Data sample;                                                   ///< valid, every attribute set NULL
    bool curve = false;                                            ///< an ellipse: decomposes into a PolyLine
    /// Compares two GetData results (the default: byte for byte).
    std::function<bool(const Data&, const Data&)> same;
};

template <class Traits> class QuadricApiTest : public OwningApiTest {
protected:
    using Data = typename Traits::Data;

    const Shape<Data>& shape()
    {
        static const Shape<Data> s = Traits::shape();
        return s;
    }

    bool same(const Data& a, const Data& b)
    {
        if (shape().same)
            return shape().same(a, b);
        return std::memcmp(&a, &b, sizeof(Data)) == 0;
    }

    TQ3GeometryObject make(const Data& data) { return own(shape().create(&data)); }

    Data dataOf(TQ3GeometryObject geometry)
    {
        Data data{};
        EXPECT_EQ(shape().getData(geometry, &data), kQ3Success);
        return data;
    }

    /// The data and the edit index, to check that a failed call changed
    /// nothing.
    struct State {
        Data data;
        unsigned long editIndex;
    };
    State stateOf(TQ3GeometryObject geometry)
    {
        State state{dataOf(geometry), Q3Shared_GetEditIndex(geometry)};
        return state;
    }
    void expectUnchanged(TQ3GeometryObject geometry, State& before, const std::string& what)
    {
        State after = stateOf(geometry);
        EXPECT_TRUE(same(before.data, after.data)) << what << ": the data changed";
        EXPECT_EQ(before.editIndex, after.editIndex) << what << ": the edit index changed";
        shape().emptyData(&after.data);
    }

    /// Every float of the data, by name.
    std::vector<FloatField<Data>> floats()
    {
        std::vector<FloatField<Data>> all;
        const char* axes[] = {"x", "y", "z"};
        for (int axis = 0; axis < 3; ++axis) {
            const auto member = shape().origin;
            all.push_back({std::string("origin.") + axes[axis],
                           [member, axis](Data& d) -> float& { return (&(d.*member).x)[axis]; }});
        }
        for (const VectorAccess<Data>& v : shape().vectors)
            for (int axis = 0; axis < 3; ++axis) {
                const auto member = v.member;
                all.push_back({std::string(v.name) + "." + axes[axis],
                               [member, axis](Data& d) -> float& { return (&(d.*member).x)[axis]; }});
            }
        for (const auto& [name, member] : shape().parameters) {
            const auto m = member;
            all.push_back({name, [m](Data& d) -> float& { return d.*m; }});
        }
        for (const FloatField<Data>& f : shape().extraFloats)
            all.push_back(f);
        return all;
    }

    /// A live object that is not of this type, and a stray pointer.
    TQ3Object wrongClass()
    {
        const TQ3Vector3D offset{1, 1, 1};
        return own(Q3TranslateTransform_New(&offset));
    }
    TQ3Object stray() { return reinterpret_cast<TQ3Object>(&m_notAnObject); }
    /// A handle that was a live object of this type.
    TQ3GeometryObject disposed()
    {
        TQ3GeometryObject geometry = shape().create(&shape().sample);
        Q3Object_Dispose(geometry);
        return geometry;
    }

    // ---- The common tests ------------------------------------------------------

    // Refusing NULL data and values that are not finite is the contract
    // suite's (GeometryContractTest.cpp); here, the message names the field.
    void aNonFiniteValueIsNamedInTheMessage()
    {
        for (const FloatField<Data>& field : floats())
            for (float bad : kNonFinite) {
                Data data = shape().sample;
                field.at(data) = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr), kQ3ErrorInvalidData);
                EXPECT_NE(std::string(Q3Error_GetMessage()).find(field.name.substr(0, field.name.find('.'))),
                          std::string::npos)
                    << "the message names " << field.name;
            }
    }

    void newRejectsShapesBeyondFloatRange()
    {
        Data data = shape().sample;
        (data.*(shape().origin)).x = 3.0e38f;
        (data.*(shape().vectors[0].member)) = TQ3Vector3D{1.0e38f, 0.0f, 0.0f};
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr), kQ3ErrorInvalidData);
    }

    void newRejectsParametersOutsideZeroToOne()
    {
        for (const auto& [name, member] : shape().parameters)
            for (float bad : {-0.01f, 1.01f, -1e30f}) {
                Data data = shape().sample;
                data.*member = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr) << name, kQ3ErrorInvalidData);
            }
    }

    /// The degenerate variants of the sample (docs/3dmf.md, Tolerances): each
    /// vector zero, each parallel to the next, the three in one plane, each
    /// range empty (both limits 0.5).
    std::vector<std::pair<std::string, Data>> degenerateVariants()
    {
        std::vector<std::pair<std::string, Data>> variants;
        const auto& vectors = shape().vectors;
        for (std::size_t i = 0; i < vectors.size(); ++i) {
            Data data = shape().sample;
            data.*(vectors[i].member) = TQ3Vector3D{0, 0, 0};
            variants.emplace_back(std::string(vectors[i].name) + " zero", data);
            const TQ3Vector3D other = data.*(vectors[(i + 1) % vectors.size()].member);
            data = shape().sample;
            data.*(vectors[i].member) = TQ3Vector3D{-2 * other.x, -2 * other.y, -2 * other.z};
            variants.emplace_back(std::string(vectors[i].name) + " parallel", data);
        }
        if (vectors.size() == 3) {
            Data data = shape().sample;
            const TQ3Vector3D a = data.*(vectors[1].member), b = data.*(vectors[2].member);
            data.*(vectors[0].member) = TQ3Vector3D{a.x + 0.5f * b.x, a.y + 0.5f * b.y, a.z + 0.5f * b.z};
            variants.emplace_back("coplanar", data);
        }
        const auto& p = shape().parameters;
        for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
            Data data = shape().sample;
            data.*(p[i].second) = 0.5f;
            data.*(p[i + 1].second) = 0.5f;
            variants.emplace_back(std::string(p[i].first) + " empty range", data);
        }
        return variants;
    }

    /// Submits `geometry` inside the loop of `v` and returns its
    /// decomposition, expected to exist (NULL if it does not).
    static TQ3GeometryObject submitAndDecompose(TQ3GeometryObject geometry, TQ3ViewObject v, const std::string& what)
    {
        EXPECT_EQ(Q3Geometry_Submit(geometry, v), kQ3Success) << what;
        TQ3GeometryObject result = Q3Geometry_GetDecomposed(geometry, v);
        EXPECT_NE(result, nullptr) << what;
        return result;
    }

    /// The interactive and the wireframe renderer each finish drawing
    /// `geometry` alone into a 64 x 48 image, which `check` then looks at.
    void expectBothRenderersFinish(TQ3GeometryObject geometry, const std::string& what,
                                   const std::function<void(const Pixmap&)>& check)
    {
        for (TQ3ObjectType renderer : {kQ3RendererTypeInteractive, kQ3RendererTypeWireFrame}) {
            Pixmap image(64, 48);
            TestView drawing(image.pixmap(), renderer);
            EXPECT_EQ(drawing.render([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(geometry, v), kQ3Success); }),
                      kQ3ViewStatusDone)
                << what;
            check(image);
        }
    }

    /// A degenerate shape draws nothing (docs/3dmf.md, Tolerances): its bounds are empty, its
    /// decomposition holds no point, and the interactive and wireframe
    /// renderers finish drawing it (Quesa's reading: it draws nothing).
    void expectDrawsNothing(TQ3GeometryObject geometry, const std::string& what)
    {
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            TQ3GeometryObject result = submitAndDecompose(geometry, v, what);
            if (result == nullptr)
                return;
            EXPECT_EQ(Q3Geometry_GetType(result), kQ3GeometryTypeTriMesh) << what;
            TQ3TriMeshData mesh{};
            EXPECT_EQ(Q3TriMesh_GetData(result, &mesh), kQ3Success);
            EXPECT_EQ(mesh.numPoints, 0u) << what;
            EXPECT_EQ(mesh.numTriangles, 0u) << what;
            Q3TriMesh_EmptyData(&mesh);
            Q3Object_Dispose(result);
        });
        EXPECT_EQ(box.isEmpty, kQ3True) << what;
        expectBothRenderersFinish(geometry, what, [&](const Pixmap& image) {
            for (unsigned long y = 0; y < image.height(); ++y)
                for (unsigned long x = 0; x < image.width(); ++x)
                    EXPECT_FALSE(image.lit(x, y)) << what << " lights pixel " << x << ", " << y;
        });
    }

    /// An ellipse whose radii are zero or parallel is a segment (or a
    /// point): a curve needs no normal, so it is drawn, with finite points
    /// and finite bounds.
    void expectDrawsASegment(TQ3GeometryObject geometry, const std::string& what)
    {
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            TQ3GeometryObject result = submitAndDecompose(geometry, v, what);
            if (result == nullptr)
                return;
            ASSERT_EQ(Q3Geometry_GetType(result), kQ3GeometryTypePolyLine) << what;
            TQ3PolyLineData line{};
            EXPECT_EQ(Q3PolyLine_GetData(result, &line), kQ3Success);
            EXPECT_GE(line.numVertices, 2u) << what;
            for (unsigned long i = 0; i < line.numVertices; ++i) {
                const TQ3Point3D& p = line.vertices[i].point;
                EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << what;
            }
            Q3PolyLine_EmptyData(&line);
            Q3Object_Dispose(result);
        });
        ASSERT_EQ(box.isEmpty, kQ3False) << what;
        for (float c : {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z})
            EXPECT_TRUE(std::isfinite(c)) << what;
        expectBothRenderersFinish(geometry, what, [](const Pixmap&) {});
    }

    /// What a degenerate variant draws: nothing, but for an ellipse's
    /// dependent radii (`frame`), its segment.
    void expectDegenerateDrawing(TQ3GeometryObject geometry, const std::string& what, bool frame)
    {
        if (shape().curve && frame)
            expectDrawsASegment(geometry, what);
        else
            expectDrawsNothing(geometry, what);
    }

    void degenerateShapesAreKeptWithAWarningAndDrawnSafely()
    {
        for (const auto& variant : degenerateVariants()) {
            const std::string& what = variant.first;
            const Data& data = variant.second;
            TQ3GeometryObject geometry = nullptr;
            EXPECT_Q3_WARNING(geometry = shape().create(&data), kQ3WarningInconsistentData);
            ASSERT_NE(geometry, nullptr) << what;
            own(geometry);
            Data out = dataOf(geometry);
            EXPECT_TRUE(same(out, data)) << what << ": GetData gives the data back unchanged";
            shape().emptyData(&out);
            const bool frame = what.find("range") == std::string::npos;
            expectDegenerateDrawing(geometry, what, frame);
            // Immediate mode posts the warning at each submit.
            const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
                EXPECT_Q3_WARNING(EXPECT_EQ(shape().submit(&data, v), kQ3Success) << what,
                                  kQ3WarningInconsistentData);
            });
            EXPECT_EQ(box.isEmpty, shape().curve && frame ? kQ3False : kQ3True) << what;
        }
        // The rules run in order, and a refused call posts its error alone: a
        // value that is not finite is reported, with no warning for the frame.
        Data data = shape().sample;
        data.*(shape().vectors[0].member) = TQ3Vector3D{0, 0, 0};
        (data.*(shape().origin)).y = kNaN;
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr), kQ3ErrorInvalidData);
    }

    void newRejectsBadAttributeSetsAfterTheOtherRules()
    {
        for (const SetAccess<Data>& set : shape().sets) {
            Data data = shape().sample;
            data.*(set.member) = wrongClass();
            EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr) << set.name, kQ3ErrorInvalidObjectType);
            data.*(set.member) = stray();
            EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr) << set.name, kQ3ErrorInvalidObject);
            // A degenerate shape refused for its set posts the error alone.
            data.*(shape().vectors[0].member) = TQ3Vector3D{0, 0, 0};
            EXPECT_Q3_ERROR(EXPECT_EQ(shape().create(&data), nullptr) << set.name, kQ3ErrorInvalidObject);
        }
    }

    void setDataReplacesAndAFailedSetDataChangesNothing()
    {
        TQ3GeometryObject geometry = make(shape().sample);
        Data next = shape().sample;
        (next.*(shape().origin)).x += 5;
        next.*(shape().own) = own(Q3AttributeSet_New());
        const unsigned long before = Q3Shared_GetEditIndex(geometry);
        ASSERT_EQ(shape().setData(geometry, &next), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), before);
        Data out = dataOf(geometry);
        EXPECT_TRUE(same(out, next));
        shape().emptyData(&out);

        State state = stateOf(geometry);
        Data bad = shape().sample;
        bad.*(shape().vectors[0].member) = TQ3Vector3D{0, kInf, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setData(geometry, &bad), kQ3Failure), kQ3ErrorInvalidData);
        bad = shape().sample;
        bad.*(shape().own) = stray();
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setData(geometry, &bad), kQ3Failure), kQ3ErrorInvalidObject);
        bad.*(shape().vectors[0].member) = TQ3Vector3D{0, 0, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setData(geometry, &bad), kQ3Failure), kQ3ErrorInvalidObject);
        expectUnchanged(geometry, state, "SetData");
        shape().emptyData(&state.data);

        // A degenerate shape is taken with the warning, kept as given, and
        // drawn as nothing; valid data afterwards draws again.
        Data flat = shape().sample;
        flat.*(shape().vectors[0].member) = TQ3Vector3D{0, 0, 0};
        const unsigned long beforeFlat = Q3Shared_GetEditIndex(geometry);
        EXPECT_Q3_WARNING(EXPECT_EQ(shape().setData(geometry, &flat), kQ3Success), kQ3WarningInconsistentData);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), beforeFlat);
        out = dataOf(geometry);
        EXPECT_TRUE(same(out, flat));
        shape().emptyData(&out);
        expectDegenerateDrawing(geometry, "SetData", true);
        ASSERT_EQ(shape().setData(geometry, &shape().sample), kQ3Success);
        TQ3BoundingBox box{};
        EXPECT_FALSE(decomposedPoints(geometry, box).empty());
        EXPECT_EQ(box.isEmpty, kQ3False);
    }

    void originAndVectorsReadBackAndFailedSetsChangeNothing()
    {
        TQ3GeometryObject geometry = make(shape().sample);
        TQ3Object wrong = wrongClass();
        // The origin.
        const TQ3Point3D origin{-3, 4.5f, 0.25f};
        unsigned long before = Q3Shared_GetEditIndex(geometry);
        ASSERT_EQ(shape().setOrigin(geometry, &origin), kQ3Success);
        EXPECT_NE(Q3Shared_GetEditIndex(geometry), before);
        TQ3Point3D point{};
        ASSERT_EQ(shape().getOrigin(geometry, &point), kQ3Success);
        EXPECT_EQ(std::memcmp(&point, &origin, sizeof point), 0);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().getOrigin(nullptr, &point), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().getOrigin(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().getOrigin(wrong, &point), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().getOrigin(disposed(), &point), kQ3Failure), kQ3ErrorInvalidObject);
        State state = stateOf(geometry);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(nullptr, &origin), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(wrong, &origin), kQ3Failure), kQ3ErrorInvalidObjectType);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(disposed(), &origin), kQ3Failure), kQ3ErrorInvalidObject);
        for (int axis = 0; axis < 3; ++axis)
            for (float bad : kNonFinite) {
                TQ3Point3D p = origin;
                (&p.x)[axis] = bad;
                EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(geometry, &p), kQ3Failure), kQ3ErrorInvalidData);
            }
        expectUnchanged(geometry, state, "SetOrigin");
        shape().emptyData(&state.data);
        // An origin that would put the shape beyond float's range.
        Data large = shape().sample;
        TQ3Vector3D& huge = large.*(shape().vectors[0].member);
        huge = TQ3Vector3D{huge.x * 1e37f, huge.y * 1e37f, huge.z * 1e37f};
        TQ3GeometryObject big = make(large);
        ASSERT_NE(big, nullptr);
        const TQ3Point3D far{std::numeric_limits<float>::max(), 0, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().setOrigin(big, &far), kQ3Failure), kQ3ErrorInvalidData);

        // The vectors.
        for (const VectorAccess<Data>& v : shape().vectors) {
            const TQ3Vector3D original = shape().sample.*(v.member);
            const TQ3Vector3D scaled{2 * original.x, 2 * original.y, 2 * original.z};
            before = Q3Shared_GetEditIndex(geometry);
            ASSERT_EQ(v.set(geometry, &scaled), kQ3Success) << v.name;
            EXPECT_NE(Q3Shared_GetEditIndex(geometry), before) << v.name;
            TQ3Vector3D got{};
            ASSERT_EQ(v.get(geometry, &got), kQ3Success);
            EXPECT_EQ(std::memcmp(&got, &scaled, sizeof got), 0) << v.name;
            EXPECT_Q3_ERROR(EXPECT_EQ(v.get(nullptr, &got), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.get(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.get(wrong, &got), kQ3Failure), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.get(disposed(), &got), kQ3Failure), kQ3ErrorInvalidObject);

            State vectorState = stateOf(geometry);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.set(nullptr, &scaled), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.set(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.set(wrong, &scaled), kQ3Failure), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(EXPECT_EQ(v.set(disposed(), &scaled), kQ3Failure), kQ3ErrorInvalidObject);
            for (int axis = 0; axis < 3; ++axis)
                for (float bad : kNonFinite) {
                    TQ3Vector3D w = scaled;
                    (&w.x)[axis] = bad;
                    EXPECT_Q3_ERROR(EXPECT_EQ(v.set(geometry, &w), kQ3Failure) << v.name, kQ3ErrorInvalidData);
                }
            expectUnchanged(geometry, vectorState, v.name);
            shape().emptyData(&vectorState.data);

            // A zero or parallel vector is taken with the warning, as SetData
            // takes it, and read back as given.
            const TQ3Vector3D zero{0, 0, 0};
            EXPECT_Q3_WARNING(EXPECT_EQ(v.set(geometry, &zero), kQ3Success) << v.name, kQ3WarningInconsistentData);
            ASSERT_EQ(v.get(geometry, &got), kQ3Success);
            EXPECT_EQ(std::memcmp(&got, &zero, sizeof got), 0) << v.name;
            ASSERT_EQ(v.set(geometry, &scaled), kQ3Success);
            for (const VectorAccess<Data>& other : shape().vectors) {
                if (other.member == v.member)
                    continue;
                TQ3Vector3D parallel{};
                other.get(geometry, &parallel);
                EXPECT_Q3_WARNING(EXPECT_EQ(v.set(geometry, &parallel), kQ3Success)
                                      << v.name << " parallel to " << other.name,
                                  kQ3WarningInconsistentData);
                ASSERT_EQ(v.set(geometry, &scaled), kQ3Success);
            }
        }
    }

    void partSetsAreReadAndReplacedWithBalancedReferences()
    {
        TQ3GeometryObject geometry = make(shape().sample);
        TQ3Object wrong = wrongClass();
        for (const SetAccess<Data>& access : shape().sets) {
            if (access.set == nullptr)
                continue;
            TQ3AttributeSet got = reinterpret_cast<TQ3AttributeSet>(&m_notAnObject);
            ASSERT_EQ(access.get(geometry, &got), kQ3Success) << access.name;
            EXPECT_EQ(got, nullptr) << access.name;
            TQ3AttributeSet set = own(Q3AttributeSet_New());
            unsigned long before = Q3Shared_GetEditIndex(geometry);
            ASSERT_EQ(access.set(geometry, set), kQ3Success) << access.name;
            EXPECT_NE(Q3Shared_GetEditIndex(geometry), before) << access.name;
            EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3True) << access.name;
            ASSERT_EQ(access.get(geometry, &got), kQ3Success);
            EXPECT_EQ(got, set) << access.name;
            Q3Object_Dispose(got);
            Data out = dataOf(geometry);
            EXPECT_EQ(out.*(access.member), set) << access.name << " is the data's " << access.name;
            shape().emptyData(&out);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.get(nullptr, &got), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.get(geometry, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.get(wrong, &got), kQ3Failure), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.get(disposed(), &got), kQ3Failure), kQ3ErrorInvalidObject);

            State state = stateOf(geometry);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.set(nullptr, set), kQ3Failure), kQ3ErrorNULLParameter);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.set(wrong, set), kQ3Failure), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.set(disposed(), set), kQ3Failure), kQ3ErrorInvalidObject);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.set(geometry, wrong), kQ3Failure), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(EXPECT_EQ(access.set(geometry, stray()), kQ3Failure), kQ3ErrorInvalidObject);
            expectUnchanged(geometry, state, access.name);
            shape().emptyData(&state.data);

            ASSERT_EQ(access.set(geometry, nullptr), kQ3Success) << access.name;
            EXPECT_EQ(Q3Shared_IsReferenced(set), kQ3False) << access.name << ": NULL releases the set";
            ASSERT_EQ(access.get(geometry, &got), kQ3Success);
            EXPECT_EQ(got, nullptr);
        }
    }

    void submitChecksItsArgumentsAndTheDataRules()
    {
        const Data& data = shape().sample;
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(&data, view()), kQ3Failure), kQ3ErrorViewNotStarted);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(nullptr, view()), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(&data, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(&data, wrongClass()), kQ3Failure), kQ3ErrorInvalidObjectType);
        TQ3GeometryObject geometry = make(data);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Geometry_Submit(geometry, view()), kQ3Failure), kQ3ErrorViewNotStarted);
        const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) {
            Data bad = data;
            (bad.*(shape().origin)).z = -kInf;
            EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(&bad, v), kQ3Failure), kQ3ErrorInvalidData);
            bad = data;
            bad.*(shape().vectors[0].member) = TQ3Vector3D{0, 0, 0};
            EXPECT_Q3_WARNING(EXPECT_EQ(shape().submit(&bad, v), kQ3Success), kQ3WarningInconsistentData);
            bad = data;
            bad.*(shape().own) = v;
            EXPECT_Q3_ERROR(EXPECT_EQ(shape().submit(&bad, v), kQ3Failure), kQ3ErrorInvalidObjectType);
        });
        // Nothing was drawn but the degenerate shape, which is nothing (an
        // ellipse's segment is something).
        EXPECT_EQ(box.isEmpty, shape().curve ? kQ3False : kQ3True);
    }

    /// The points Q3 draws for a geometry in a bounding loop (world space
    /// 0.05, so fine), with the bounding box of the same loop.
    std::vector<TQ3Point3D> decomposedPoints(TQ3GeometryObject geometry, TQ3BoundingBox& box,
                                             TQ3GeometryObject* decomposed = nullptr)
    {
        std::vector<TQ3Point3D> points;
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodWorldSpace, 0.05f, 0.05f};
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        do {
            EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, view()), kQ3Success);
            EXPECT_EQ(Q3Geometry_Submit(geometry, view()), kQ3Success);
            TQ3GeometryObject result = Q3Geometry_GetDecomposed(geometry, view());
            EXPECT_NE(result, nullptr);
            points.clear();
            if (result != nullptr) {
                if (shape().curve) {
                    EXPECT_EQ(Q3Geometry_GetType(result), kQ3GeometryTypePolyLine);
                    TQ3PolyLineData line{};
                    EXPECT_EQ(Q3PolyLine_GetData(result, &line), kQ3Success);
                    for (unsigned long i = 0; i < line.numVertices; ++i)
                        points.push_back(line.vertices[i].point);
                    Q3PolyLine_EmptyData(&line);
                } else {
                    EXPECT_EQ(Q3Geometry_GetType(result), kQ3GeometryTypeTriMesh);
                    TQ3TriMeshData mesh{};
                    EXPECT_EQ(Q3TriMesh_GetData(result, &mesh), kQ3Success);
                    points.assign(mesh.points, mesh.points + mesh.numPoints);
                    bool normals = false, uvs = false;
                    for (unsigned long a = 0; a < mesh.numVertexAttributeTypes; ++a) {
                        normals |= mesh.vertexAttributeTypes[a].attributeType == kQ3AttributeTypeNormal;
                        uvs |= mesh.vertexAttributeTypes[a].attributeType == kQ3AttributeTypeSurfaceUV;
                    }
                    EXPECT_TRUE(normals && uvs) << "every vertex has a normal and a surface uv";
                    EXPECT_GT(mesh.numTriangles, 0u);
                    Q3TriMesh_EmptyData(&mesh);
                }
                if (decomposed != nullptr)
                    *decomposed = own(result);
                else
                    Q3Object_Dispose(result);
            }
        } while (Q3View_EndBoundingBox(view(), &box) == kQ3ViewStatusRetraverse);
        return points;
    }

    void boundsHoldWhatIsDrawnAndDecompositionFollowsEdits()
    {
        TQ3AttributeSet ownSet = own(Q3AttributeSet_New());
        Data data = shape().sample;
        data.*(shape().own) = ownSet;
        TQ3GeometryObject geometry = make(data);
        TQ3BoundingBox box{};
        TQ3GeometryObject result = nullptr;
        const std::vector<TQ3Point3D> points = decomposedPoints(geometry, box, &result);
        ASSERT_FALSE(points.empty());
        ASSERT_EQ(box.isEmpty, kQ3False);
        for (const TQ3Point3D& p : points) {
            EXPECT_GE(p.x, box.min.x - 1e-5f);
            EXPECT_LE(p.x, box.max.x + 1e-5f);
            EXPECT_GE(p.y, box.min.y - 1e-5f);
            EXPECT_LE(p.y, box.max.y + 1e-5f);
            EXPECT_GE(p.z, box.min.z - 1e-5f);
            EXPECT_LE(p.z, box.max.z + 1e-5f);
        }
        // The decomposition carries the shape's own set.
        TQ3AttributeSet carried = nullptr;
        ASSERT_EQ(Q3Geometry_GetAttributeSet(result, &carried), kQ3Success);
        EXPECT_EQ(carried, ownSet);
        if (carried != nullptr)
            Q3Object_Dispose(carried);
        // Immediate mode draws the same.
        TQ3BoundingBox immediate = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(shape().submit(&data, v), kQ3Success); });
        EXPECT_EQ(std::memcmp(&immediate, &box, sizeof box), 0);
        // An edit is drawn.
        const TQ3Point3D moved{100, 0, 0};
        ASSERT_EQ(shape().setOrigin(geometry, &moved), kQ3Success);
        const std::vector<TQ3Point3D> after = decomposedPoints(geometry, box);
        ASSERT_FALSE(after.empty());
        EXPECT_GT(after.front().x, 50.0f);
    }

    unsigned char m_notAnObject[64] = {};
};

} // namespace q3test

/// The tests every quadric and solid type runs (Fixture derives from
/// QuadricApiTest).
#define Q3_QUADRIC_API_TESTS(Fixture)                                                                                  \
    TEST_F(Fixture, ANonFiniteValueIsNamedInTheMessage)                                                                \
    {                                                                                                                  \
        aNonFiniteValueIsNamedInTheMessage();                                                                        \
    }                                                                                                                  \
    TEST_F(Fixture, NewRejectsShapesBeyondFloatRange)                                                                  \
    {                                                                                                                  \
        newRejectsShapesBeyondFloatRange();                                                                            \
    }                                                                                                                  \
    TEST_F(Fixture, NewRejectsParametersOutsideZeroToOne)                                                              \
    {                                                                                                                  \
        newRejectsParametersOutsideZeroToOne();                                                                        \
    }                                                                                                                  \
    TEST_F(Fixture, DegenerateShapesAreKeptWithAWarningAndDrawnSafely)                                                 \
    {                                                                                                                  \
        degenerateShapesAreKeptWithAWarningAndDrawnSafely();                                                           \
    }                                                                                                                  \
    TEST_F(Fixture, NewRejectsBadAttributeSetsAfterTheOtherRules)                                                      \
    {                                                                                                                  \
        newRejectsBadAttributeSetsAfterTheOtherRules();                                                                \
    }                                                                                                                  \
    TEST_F(Fixture, SetDataReplacesAndAFailedSetDataChangesNothing)                                                    \
    {                                                                                                                  \
        setDataReplacesAndAFailedSetDataChangesNothing();                                                              \
    }                                                                                                                  \
    TEST_F(Fixture, OriginAndVectorsReadBackAndFailedSetsChangeNothing)                                                \
    {                                                                                                                  \
        originAndVectorsReadBackAndFailedSetsChangeNothing();                                                          \
    }                                                                                                                  \
    TEST_F(Fixture, PartSetsAreReadAndReplacedWithBalancedReferences)                                                  \
    {                                                                                                                  \
        partSetsAreReadAndReplacedWithBalancedReferences();                                                            \
    }                                                                                                                  \
    TEST_F(Fixture, SubmitChecksItsArgumentsAndTheDataRules)                                                           \
    {                                                                                                                  \
        submitChecksItsArgumentsAndTheDataRules();                                                                     \
    }                                                                                                                  \
    TEST_F(Fixture, BoundsHoldWhatIsDrawnAndDecompositionFollowsEdits)                                                 \
    {                                                                                                                  \
        boundsHoldWhatIsDrawnAndDecompositionFollowsEdits();                                                           \
    }

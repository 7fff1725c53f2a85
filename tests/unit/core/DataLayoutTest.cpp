// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// core/DataLayout.h on a test struct described with every field kind: the
// structural check (required arrays, the count limit, saturating counts),
// deep copies under the three handle policies with their strong guarantee
// (a dead handle deep inside leaves nothing retained), release, the handle
// check and the handle walk. Reference counts and live objects are read
// from the core directly; leaked memory would show under LeakSanitizer.

#include "core/AttributeSet.h"
#include "core/DataLayout.h"
#include "style/SubdivisionStyle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

// An element that is itself described: a value and a handle.
struct Leaf {
    TQ3Point3D point;
    TQ3AttributeSet set;
};

// Every field kind DataLayout.h has.
struct Sample {
    int tag;                   // value
    unsigned long numLeaves;   // value (a count)
    Leaf* leaves;              // array of described elements, required
    Leaf fixed[2];             // inline array of described elements
    unsigned long numValues;   // value (a count)
    float* values;             // optional array of plain elements
    TQ3AttributeSet* sets;     // optional handle array, numLeaves entries
    unsigned long rows, cols;  // values
    float* grid;               // required array of rows * cols
    std::uint16_t* extra;      // optional array of numLeaves + numValues
    TQ3AttributeSet whole;     // handle
};

} // namespace

namespace q3::layout {

template <>
struct Describe<Leaf> {
    static auto fields()
    {
        return std::make_tuple(value("point", &Leaf::point), handle<AttributeSet>("set", &Leaf::set));
    }
};

template <>
struct Describe<Sample> {
    static auto fields()
    {
        return std::make_tuple(value("tag", &Sample::tag), value("numLeaves", &Sample::numLeaves),
                               array("leaves", &Sample::leaves, countOf(&Sample::numLeaves)),
                               inlineArray("fixed", &Sample::fixed), value("numValues", &Sample::numValues),
                               optionalArray("values", &Sample::values, countOf(&Sample::numValues)),
                               optionalHandleArray<AttributeSet>("sets", &Sample::sets, countOf(&Sample::numLeaves)),
                               value("rows", &Sample::rows), value("cols", &Sample::cols),
                               array("grid", &Sample::grid, countProduct(&Sample::rows, &Sample::cols)),
                               optionalArray("extra", &Sample::extra, countSum(&Sample::numLeaves, &Sample::numValues)),
                               handle<AttributeSet>("whole", &Sample::whole));
    }
};

// The rules a description states beyond presence and the limit: a minimum
// count, finite values and finite elements.
struct Counted {
    unsigned long n;
    TQ3Point3D* points;
    float scale;
};

template <>
struct Describe<Counted> {
    static auto fields()
    {
        return std::make_tuple(atLeast("n", &Counted::n, 2),
                               finiteElements(requiredArray("points", &Counted::points, countOf(&Counted::n))),
                               finite("scale", &Counted::scale));
    }
};

} // namespace q3::layout

namespace q3 {
namespace {

using layout::Counted;
using layout::Path;

TQ3Error codeOf(const std::function<void()>& call, std::string* message = nullptr)
{
    try {
        call();
    } catch (const Error& error) {
        if (message != nullptr)
            *message = error.what();
        return error.code();
    }
    return kQ3ErrorNone;
}

unsigned long referencesOf(TQ3AttributeSet handle)
{
    return layout::heldObject(handle)->referenceCount();
}

class DataLayoutTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_liveAtStart = liveObjectCount();
        for (Ref<AttributeSet>& set : m_sets)
            set = makeShared<AttributeSet>();
        m_leaves = {{{1, 2, 3}, a()}, {{4, 5, 6}, nullptr}, {{7, 8, 9}, a()}, {{0, 0, 0}, b()}};
        m_values = {0.5f, 1.5f};
        m_handles = {b(), nullptr, a(), c()};
        m_grid = {1, 2, 3, 4, 5, 6};
        m_extra = {10, 11, 12, 13, 14, 15};
        m_data.tag = 42;
        m_data.numLeaves = m_leaves.size();
        m_data.leaves = m_leaves.data();
        m_data.fixed[0] = Leaf{{-1, -1, -1}, c()};
        m_data.fixed[1] = Leaf{{-2, -2, -2}, nullptr};
        m_data.numValues = m_values.size();
        m_data.values = m_values.data();
        m_data.sets = m_handles.data();
        m_data.rows = 2;
        m_data.cols = 3;
        m_data.grid = m_grid.data();
        m_data.extra = m_extra.data();
        m_data.whole = a();
    }

    void TearDown() override
    {
        for (Ref<AttributeSet>& set : m_sets)
            set.reset();
        EXPECT_EQ(liveObjectCount(), m_liveAtStart);
    }

    TQ3AttributeSet a() const { return m_sets[0]->handle(); }
    TQ3AttributeSet b() const { return m_sets[1]->handle(); }
    TQ3AttributeSet c() const { return m_sets[2]->handle(); }

    // How often each of a, b, c appears in m_data (every handle field).
    static constexpr unsigned long kUsesOfA = 4, kUsesOfB = 2, kUsesOfC = 2;

    void expectOnlyOurReferences() const
    {
        for (const Ref<AttributeSet>& set : m_sets)
            EXPECT_EQ(set->referenceCount(), 1u);
    }

    // Checks that dst is a deep copy of m_data: equal values, fresh arrays.
    void expectDeepCopy(const Sample& dst) const
    {
        EXPECT_EQ(dst.tag, 42);
        ASSERT_EQ(dst.numLeaves, m_leaves.size());
        ASSERT_NE(dst.leaves, nullptr);
        EXPECT_NE(dst.leaves, m_data.leaves);
        for (std::size_t i = 0; i < m_leaves.size(); ++i)
            EXPECT_EQ(dst.leaves[i].point.x, m_leaves[i].point.x) << i;
        EXPECT_EQ(dst.fixed[0].point.y, -1.0f);
        EXPECT_EQ(dst.fixed[1].point.z, -2.0f);
        ASSERT_NE(dst.values, nullptr);
        EXPECT_NE(dst.values, m_data.values);
        EXPECT_EQ(dst.values[1], 1.5f);
        ASSERT_NE(dst.sets, nullptr);
        EXPECT_NE(dst.sets, m_data.sets);
        ASSERT_NE(dst.grid, nullptr);
        EXPECT_NE(dst.grid, m_data.grid);
        EXPECT_EQ(std::memcmp(dst.grid, m_grid.data(), 6 * sizeof(float)), 0);
        ASSERT_NE(dst.extra, nullptr);
        EXPECT_NE(dst.extra, m_data.extra);
        EXPECT_EQ(std::memcmp(dst.extra, m_extra.data(), 6 * sizeof(std::uint16_t)), 0);
    }

    static void expectNothingOwned(const Sample& s)
    {
        EXPECT_EQ(s.leaves, nullptr);
        EXPECT_EQ(s.fixed[0].set, nullptr);
        EXPECT_EQ(s.fixed[1].set, nullptr);
        EXPECT_EQ(s.values, nullptr);
        EXPECT_EQ(s.sets, nullptr);
        EXPECT_EQ(s.grid, nullptr);
        EXPECT_EQ(s.extra, nullptr);
        EXPECT_EQ(s.whole, nullptr);
    }

    Ref<AttributeSet> m_sets[3];
    std::vector<Leaf> m_leaves;
    std::vector<float> m_values;
    std::vector<TQ3AttributeSet> m_handles;
    std::vector<float> m_grid;
    std::vector<std::uint16_t> m_extra;
    Sample m_data{};
    unsigned long m_liveAtStart = 0;
};

// ---- Counts and the structural check ---------------------------------------------

TEST_F(DataLayoutTest, CountSumAndCountProductSaturateInsteadOfWrapping)
{
    constexpr std::size_t kMax = ~std::size_t{0};
    Sample s{};
    const auto sum = layout::countSum(&Sample::numLeaves, &Sample::numValues);
    const auto product = layout::countProduct(&Sample::rows, &Sample::cols);
    s.numLeaves = 3;
    s.numValues = 4;
    s.rows = 5;
    s.cols = 6;
    EXPECT_EQ(sum(s), 7u);
    EXPECT_EQ(product(s), 30u);
    s.numLeaves = std::numeric_limits<unsigned long>::max();
    s.numValues = 1; // wraps to 0
    EXPECT_EQ(sum(s), kMax);
    s.rows = s.cols = 1UL << 32; // wraps to 0
    EXPECT_EQ(product(s), kMax);
    s.rows = (1UL << 32) + 1; // wraps to 2^32 + 1... far from the truth
    EXPECT_EQ(product(s), kMax);
    s.rows = 0;
    EXPECT_EQ(product(s), 0u);
    s.rows = 7;
    s.cols = 0;
    EXPECT_EQ(product(s), 0u);
}

TEST_F(DataLayoutTest, CheckStructureAcceptsValidDataAndNullOptionalArrays)
{
    EXPECT_EQ(codeOf([&] { layout::checkStructure(m_data, Path{}); }), kQ3ErrorNone);
    Sample s = m_data;
    s.values = nullptr;
    s.sets = nullptr;
    s.extra = nullptr;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }), kQ3ErrorNone);
    // A required array may be NULL when its count is 0.
    s.rows = 0;
    s.grid = nullptr;
    s.numLeaves = 0;
    s.leaves = nullptr;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }), kQ3ErrorNone);
}

TEST_F(DataLayoutTest, CheckStructureRejectsANullRequiredArray)
{
    std::string message;
    Sample s = m_data;
    s.leaves = nullptr;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }, &message), kQ3ErrorNULLParameter);
    EXPECT_NE(message.find("leaves"), std::string::npos) << message;
    s = m_data;
    s.grid = nullptr;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }, &message), kQ3ErrorNULLParameter);
    EXPECT_NE(message.find("grid"), std::string::npos) << message;
}

TEST_F(DataLayoutTest, CheckStructureRejectsCountsAboveTheLimitWithoutReadingTheArrays)
{
    const unsigned long tooMany = (unsigned long)limits::kMaxArrayCount + 1;
    std::string message;
    struct Case {
        const char* name;
        std::function<void(Sample&)> set;
    };
    const Case cases[] = {
        {"leaves", [&](Sample& s) { s.numLeaves = tooMany; }},
        {"values", [&](Sample& s) { s.numValues = tooMany; }},
        {"grid", [&](Sample& s) { s.rows = tooMany; }},
        // 2^32 * 2^32 wraps to 0 without saturation.
        {"grid", [&](Sample& s) { s.rows = s.cols = 1UL << 32; }},
    };
    for (const Case& c : cases) {
        Sample s = m_data;
        c.set(s);
        EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }, &message), kQ3ErrorParameterOutOfRange)
            << c.name;
        EXPECT_NE(message.find(c.name), std::string::npos) << message;
    }
    // Exactly at the limit is allowed (only counted, never read: the arrays
    // are NULL): values and extra (numLeaves + numValues) both at the limit.
    Sample s = m_data;
    s.values = nullptr;
    s.extra = nullptr;
    s.numValues = limits::kMaxArrayCount - s.numLeaves;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }), kQ3ErrorNone);
}

TEST_F(DataLayoutTest, CheckStructureReportsEveryNullBeforeAnyCount)
{
    // A count above the limit in an earlier field, a NULL array in a later
    // one: presence is checked over the whole struct first.
    Sample s = m_data;
    s.numLeaves = (unsigned long)limits::kMaxArrayCount + 1;
    s.grid = nullptr;
    std::string message;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(s, Path{}); }, &message), kQ3ErrorNULLParameter);
    EXPECT_NE(message.find("grid"), std::string::npos) << message;
}

TEST_F(DataLayoutTest, CheckStructureChecksPresenceThenMinimumThenMaximumThenValues)
{
    TQ3Point3D points[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    const Counted good{3, points, 1.0f};
    EXPECT_EQ(codeOf([&] { layout::checkStructure(good, Path{}); }), kQ3ErrorNone);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::string message;
    // A required array is NULL even with no entries; before the minimum.
    EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{0, nullptr, nan}, Path{}); }), kQ3ErrorNULLParameter);
    // The minimum, before a value that is not finite.
    EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{1, points, nan}, Path{}); }, &message),
              kQ3ErrorGeometryInsufficientNumberOfPoints);
    EXPECT_NE(message.find("n is 1"), std::string::npos) << message;
    // The maximum, without reading the three points as more.
    EXPECT_EQ(codeOf([&] {
                  layout::checkStructure(Counted{(unsigned long)limits::kMaxArrayCount + 1, points, nan}, Path{});
              }),
              kQ3ErrorParameterOutOfRange);
    // The values: the field and every element.
    EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{3, points, nan}, Path{}); }, &message),
              kQ3ErrorInvalidData);
    EXPECT_NE(message.find("scale"), std::string::npos) << message;
    for (float bad : {nan, std::numeric_limits<float>::infinity()}) {
        points[1].y = bad;
        EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{3, points, 1.0f}, Path{}); }, &message),
                  kQ3ErrorInvalidData);
        EXPECT_NE(message.find("points[1]"), std::string::npos) << message;
    }
    // Elements past the count are not read.
    EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{2, points, 1.0f}, Path{}); }), kQ3ErrorInvalidData);
    points[1].y = 1;
    points[2].x = nan;
    EXPECT_EQ(codeOf([&] { layout::checkStructure(Counted{2, points, 1.0f}, Path{}); }), kQ3ErrorNone);
}

// ---- Copies ---------------------------------------------------------------------------

TEST_F(DataLayoutTest, RetainCheckedCopiesDeeplyAndReleaseGivesEverythingBack)
{
    Sample copy;
    std::memset(&copy, 0xAB, sizeof copy); // overwritten, not released
    layout::copyData(copy, m_data, layout::RetainChecked{});
    expectDeepCopy(copy);
    EXPECT_EQ(copy.leaves[0].set, a());
    EXPECT_EQ(copy.leaves[3].set, b());
    EXPECT_EQ(copy.fixed[0].set, c());
    EXPECT_EQ(copy.sets[3], c());
    EXPECT_EQ(copy.sets[1], nullptr);
    EXPECT_EQ(copy.whole, a());
    EXPECT_EQ(m_sets[0]->referenceCount(), 1 + kUsesOfA);
    EXPECT_EQ(m_sets[1]->referenceCount(), 1 + kUsesOfB);
    EXPECT_EQ(m_sets[2]->referenceCount(), 1 + kUsesOfC);
    EXPECT_EQ(liveObjectCount(), m_liveAtStart + 3);

    // The copy is independent of the source.
    m_leaves[0].point.x = 99;
    m_grid[5] = 99;
    EXPECT_EQ(copy.leaves[0].point.x, 1.0f);
    EXPECT_EQ(copy.grid[5], 6.0f);

    layout::release(copy);
    expectNothingOwned(copy);
    expectOnlyOurReferences();
    layout::release(copy); // a second release finds nothing
    expectOnlyOurReferences();
}

TEST_F(DataLayoutTest, RetainCheckedFailsOnADeadOrWrongHandleAnywhereAndKeepsNothing)
{
    // A handle that is not a live attribute set, placed in each handle slot
    // in turn (after and before live handles in other slots).
    Ref<AttributeSet> doomed = makeShared<AttributeSet>();
    const TQ3Object dead = doomed->handle();
    doomed.reset();
    const TQ3SubdivisionStyleData styleData{kQ3SubdivisionMethodConstant, 4, 4};
    Ref<SubdivisionStyle> style = makeShared<SubdivisionStyle>(styleData);
    const unsigned long live = liveObjectCount();

    struct Slot {
        const char* path;
        std::function<TQ3Object&(Sample&)> at;
    };
    const Slot slots[] = {
        {"leaves[2].set", [](Sample& s) -> TQ3Object& { return s.leaves[2].set; }},
        {"leaves[3].set", [](Sample& s) -> TQ3Object& { return s.leaves[3].set; }},
        {"fixed[1].set", [](Sample& s) -> TQ3Object& { return s.fixed[1].set; }},
        {"sets[3]", [](Sample& s) -> TQ3Object& { return s.sets[3]; }},
        {"whole", [](Sample& s) -> TQ3Object& { return s.whole; }},
    };
    for (const Slot& slot : slots)
        for (const auto& [bad, code] : {std::pair{dead, kQ3ErrorInvalidObject},
                                        std::pair{TQ3Object(style->handle()), kQ3ErrorInvalidObjectType}}) {
            SCOPED_TRACE(slot.path);
            std::vector<Leaf> leaves = m_leaves;
            std::vector<TQ3AttributeSet> handles = m_handles;
            Sample source = m_data;
            source.leaves = leaves.data();
            source.sets = handles.data();
            slot.at(source) = bad;
            Sample copy;
            std::string message;
            EXPECT_EQ(codeOf([&] { layout::copyData(copy, source, layout::RetainChecked{}); }, &message), code);
            EXPECT_NE(message.find(slot.path), std::string::npos) << message;
            expectNothingOwned(copy);
            expectOnlyOurReferences();
            EXPECT_EQ(style->referenceCount(), 1u);
            EXPECT_EQ(liveObjectCount(), live);
        }
}

TEST_F(DataLayoutTest, RetainTrustedAddsOneReferencePerHandle)
{
    Sample owned;
    layout::copyData(owned, m_data, layout::RetainChecked{});
    Sample out;
    layout::copyData(out, owned, layout::RetainTrusted{});
    expectDeepCopy(out);
    EXPECT_NE(out.leaves, owned.leaves);
    EXPECT_EQ(m_sets[0]->referenceCount(), 1 + 2 * kUsesOfA);
    EXPECT_EQ(m_sets[2]->referenceCount(), 1 + 2 * kUsesOfC);
    layout::release(out);
    layout::release(owned);
    expectOnlyOurReferences();
}

TEST_F(DataLayoutTest, DuplicateEachCopiesEveryDistinctObjectOnceAndSharesTheCopy)
{
    Ref<AttributeSet> colored = makeShared<AttributeSet>();
    const TQ3ColorRGB red{1, 0, 0};
    colored->add(kQ3AttributeTypeDiffuseColor, &red);
    m_data.fixed[1].set = colored->handle();
    const unsigned long live = liveObjectCount();
    Sample copy;
    layout::copyData(copy, m_data, layout::DuplicateEach{});
    expectDeepCopy(copy);
    // One new object per distinct original (a, b, c, colored).
    EXPECT_EQ(liveObjectCount(), live + 4);
    expectOnlyOurReferences();
    EXPECT_EQ(colored->referenceCount(), 1u);

    const TQ3Object copyOfA = copy.whole;
    ASSERT_NE(copyOfA, nullptr);
    EXPECT_NE(copyOfA, a());
    EXPECT_EQ(copy.leaves[0].set, copyOfA);
    EXPECT_EQ(copy.leaves[2].set, copyOfA);
    EXPECT_EQ(copy.sets[2], copyOfA);
    EXPECT_EQ(referencesOf(copyOfA), kUsesOfA); // held once per use, nothing else
    EXPECT_EQ(copy.leaves[3].set, copy.sets[0]); // b's copy, shared
    EXPECT_NE(copy.leaves[3].set, b());
    EXPECT_EQ(referencesOf(copy.leaves[3].set), kUsesOfB);
    EXPECT_EQ(copy.fixed[0].set, copy.sets[3]); // c's copy
    EXPECT_EQ(referencesOf(copy.fixed[0].set), kUsesOfC);
    ASSERT_NE(copy.fixed[1].set, colored->handle());
    const auto* copiedColor = static_cast<const AttributeSet*>(layout::heldObject(copy.fixed[1].set));
    EXPECT_EQ(copiedColor->diffuseColor()->r, 1.0f);
    EXPECT_EQ(copy.leaves[1].set, nullptr);
    EXPECT_EQ(copy.sets[1], nullptr);

    layout::release(copy);
    EXPECT_EQ(liveObjectCount(), live); // the copies went with their last holder
}

TEST_F(DataLayoutTest, CopyingNullOptionalArraysLeavesThemNull)
{
    m_data.values = nullptr;
    m_data.sets = nullptr;
    m_data.extra = nullptr;
    Sample copy;
    layout::copyData(copy, m_data, layout::RetainChecked{});
    EXPECT_EQ(copy.values, nullptr);
    EXPECT_EQ(copy.sets, nullptr);
    EXPECT_EQ(copy.extra, nullptr);
    EXPECT_EQ(copy.numValues, 2u); // counts are copied as they are
    layout::release(copy);
    expectOnlyOurReferences();
}

// ---- Handles without copies -----------------------------------------------------------

TEST_F(DataLayoutTest, CheckHandlesFindsABadHandleAndRetainsNothing)
{
    EXPECT_EQ(codeOf([&] { layout::checkHandles(m_data, Path{}); }), kQ3ErrorNone);
    expectOnlyOurReferences();
    Ref<AttributeSet> doomed = makeShared<AttributeSet>();
    const TQ3Object dead = doomed->handle();
    doomed.reset();
    m_handles[1] = dead;
    std::string message;
    EXPECT_EQ(codeOf([&] { layout::checkHandles(m_data, Path{}); }, &message), kQ3ErrorInvalidObject);
    EXPECT_NE(message.find("sets[1]"), std::string::npos) << message;
    expectOnlyOurReferences();
}

TEST_F(DataLayoutTest, EmptyDataChecksEveryHandleBeforeReleasingAny)
{
    Sample owned;
    layout::copyData(owned, m_data, layout::RetainChecked{});
    int notAnObject = 0;
    TQ3AttributeSet const kept = owned.leaves[3].set;
    owned.leaves[3].set = reinterpret_cast<TQ3Object>(&notAnObject); // the last array element
    EXPECT_EQ(codeOf([&] { layout::emptyData(owned); }), kQ3ErrorInvalidObject);
    EXPECT_NE(owned.leaves, nullptr); // nothing freed
    EXPECT_EQ(m_sets[0]->referenceCount(), 1 + kUsesOfA);
    owned.leaves[3].set = kept;
    EXPECT_EQ(codeOf([&] { layout::emptyData(owned); }), kQ3ErrorNone);
    expectNothingOwned(owned);
    expectOnlyOurReferences();
}

TEST_F(DataLayoutTest, ForEachHandleVisitsEveryHandleOnce)
{
    std::vector<TQ3Object> seen;
    layout::forEachHandle(m_data, [&](TQ3Object handle) { seen.push_back(handle); });
    EXPECT_EQ(std::count(seen.begin(), seen.end(), a()), long(kUsesOfA));
    EXPECT_EQ(std::count(seen.begin(), seen.end(), b()), long(kUsesOfB));
    EXPECT_EQ(std::count(seen.begin(), seen.end(), c()), long(kUsesOfC));
    EXPECT_EQ(seen.size(), kUsesOfA + kUsesOfB + kUsesOfC);
}

TEST(DataLayoutPath, NamesNestedFieldsAndElements)
{
    const Path root{};
    const Path leaves = root.child("leaves");
    EXPECT_EQ(leaves.element(3).child("set").str(), "leaves[3].set");
    EXPECT_EQ(root.child("whole").str(), "whole");
    EXPECT_EQ(root.str(), "data");
}

} // namespace
} // namespace q3

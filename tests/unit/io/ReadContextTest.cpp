// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// io::ReadContext at the unit level: a Reference object resolved through
// the table of contents, in the text encoding and in both binary byte
// orders; two references giving one object (read once, shared); the
// reference ID of an object read; a reference to nothing refused.

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "core/Error.h"
#include "io/ClassIO.h"
#include "io/Metafile.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace q3::io {
namespace {

TQ3Error codeOf(const std::function<void()>& call)
{
    try {
        call();
    } catch (const Error& error) {
        return error.code();
    }
    return kQ3ErrorNone;
}

class ReadContextTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_EQ(Q3Initialize(), kQ3Success); }
    void TearDown() override { Q3Exit(); }
};

std::unique_ptr<Metafile> parseText(const std::string& text)
{
    return parse(std::vector<unsigned char>(text.begin(), text.end()), typeOfName);
}

// A binary file: a point (1, 2, 3) at byte 24, a Reference to ID 1 twice, a
// reference to ID `dangling`, and a table of contents giving ID 1 to the
// point.
std::vector<unsigned char> binaryFile(bool little, std::uint32_t dangling)
{
    std::vector<unsigned char> out;
    auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out.push_back(static_cast<unsigned char>(v >> (little ? 8 * i : 24 - 8 * i)));
    };
    auto u64 = [&](std::uint64_t v) {
        u32(static_cast<std::uint32_t>(little ? v : v >> 32));
        u32(static_cast<std::uint32_t>(little ? v >> 32 : v));
    };
    auto f32 = [&](float f) {
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        u32(bits);
    };
    const std::uint64_t toc = 24 + 20 + 3 * 12;
    u32(Q3_OBJECT_TYPE('3', 'D', 'M', 'F'));
    u32(16);
    u32(little ? (6u << 16 | 1u) : (1u << 16 | 6u));
    u32(kQ3FileModeNormal);
    u64(toc);
    u32(kQ3GeometryTypePoint);
    u32(12);
    f32(1);
    f32(2);
    f32(3);
    for (std::uint32_t id : {1u, 1u, dangling}) {
        u32(kTypeReference);
        u32(4);
        u32(id);
    }
    u32(kTypeTableOfContents);
    u32(8 + 4 * 5 + 12);
    u64(0);
    u32(2);  // reference seed
    u32(0);  // type seed
    u32(0);  // entry type 0: ID and location
    u32(12); // entry size
    u32(1);
    u32(1);
    u64(24);
    return out;
}

TEST_F(ReadContextTest, TwoReferencesGiveTheOneObjectTheTableOfContentsNames)
{
    const std::string text = "3DMetafile ( 1 6 Normal toc> )\n"
                             "p: Point ( 1 2 3 )\n"
                             "Reference ( 1 )\nReference ( 1 )\nReference ( 9 )\n"
                             "toc: TableOfContents ( 0 2 0 0 12 1 1 p> )\n";
    std::vector<std::unique_ptr<Metafile>> files;
    files.push_back(parseText(text));
    files.push_back(parse(binaryFile(false, 9), typeOfName));
    files.push_back(parse(binaryFile(true, 9), typeOfName));
    for (const auto& file : files) {
        SCOPED_TRACE(int(file->encoding));
        ASSERT_EQ(file->objects.size(), 4u);
        ReadContext context(*file);
        const Ref<SharedObject> first = context.object(file->objects[1]);
        const Ref<SharedObject> second = context.object(file->objects[2]);
        const Ref<SharedObject> direct = context.object(file->objects[0]);
        ASSERT_TRUE(first);
        EXPECT_TRUE(first->isType(kQ3GeometryTypePoint));
        EXPECT_EQ(first.get(), second.get()); // read once, shared
        EXPECT_EQ(first.get(), direct.get());
        EXPECT_EQ(context.refIdOf(*first), 1u);
        TQ3PointData data{};
        ASSERT_EQ(Q3Point_GetData(static_cast<TQ3GeometryObject>(static_cast<Object*>(first.get())), &data),
                  kQ3Success);
        EXPECT_EQ(data.point.x, 1.0f);
        EXPECT_EQ(data.point.z, 3.0f);
        Q3Point_EmptyData(&data);
        // A reference to an ID no table of contents gives.
        EXPECT_EQ(codeOf([&] { context.object(file->objects[3]); }), kQ3ErrorInvalidMetafileObject);
    }
}

TEST_F(ReadContextTest, AnObjectWithoutAnEntryHasNoReferenceId)
{
    const auto file = parseText("3DMetafile ( 1 6 Normal )\nPoint ( 1 2 3 )\n");
    ReadContext context(*file);
    const Ref<SharedObject> point = context.object(file->objects[0]);
    ASSERT_TRUE(point);
    EXPECT_EQ(context.refIdOf(*point), 0u);
}

} // namespace
} // namespace q3::io

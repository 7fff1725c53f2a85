// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The fixture every API test uses. It initializes Q3, records every error,
// warning and notice through the registered callbacks (exactly what an
// application sees), and fails the test on any that the test did not consume
// with EXPECT_Q3_ERROR / EXPECT_Q3_WARNING / EXPECT_Q3_NOTICE. It also fails a
// test that leaves Q3 objects alive.

#include "QD3D.h"
#include "QD3DErrors.h"

#include <gtest/gtest.h>

#include <cstring>
#include <mutex>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace q3test {

enum class Kind { Error, Warning, Notice };

struct Posted {
    Kind kind;
    long code;
    std::string message;
};

class Q3ApiTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_EQ(Q3Initialize(), kQ3Success);
        m_liveAtStart = Q3Memory_CountLiveObjects();
        {
            std::lock_guard<std::mutex> lock(mutex());
            posted().clear();
        }
        Q3Error_Register(&onError, 0);
        Q3Warning_Register(&onWarning, 0);
        Q3Notice_Register(&onNotice, 0);
    }

    void TearDown() override
    {
        std::vector<Posted> left;
        {
            std::lock_guard<std::mutex> lock(mutex());
            left.swap(posted());
        }
        for (const Posted& p : left)
            ADD_FAILURE() << "unexpected " << kindName(p.kind) << " " << p.code << ": " << p.message;
        EXPECT_EQ(Q3Memory_CountLiveObjects(), m_liveAtStart) << "the test leaked Q3 objects";
        Q3Error_Register(nullptr, 0);
        Q3Warning_Register(nullptr, 0);
        Q3Notice_Register(nullptr, 0);
        Q3Exit();
    }

    /// Consumes the oldest recorded post of that kind and code; fails if none.
    void consume(Kind kind, long code, const char* what, const char* file, int line)
    {
        std::lock_guard<std::mutex> lock(mutex());
        auto& list = posted();
        for (auto it = list.begin(); it != list.end(); ++it) {
            if (it->kind == kind && it->code == code) {
                list.erase(it);
                return;
            }
        }
        std::string seen;
        for (const Posted& p : list)
            seen += " " + std::string(kindName(p.kind)) + " " + std::to_string(p.code);
        ADD_FAILURE_AT(file, line) << what << ": expected " << kindName(kind) << " " << code
                                   << " was not posted; posted:" << (seen.empty() ? " nothing" : seen);
    }

    /// Drops everything recorded so far (for tests that only check results).
    void forgetPosted()
    {
        std::lock_guard<std::mutex> lock(mutex());
        posted().clear();
    }

    /// For a call whose arguments are all pointers, the last one its result
    /// (QD3DMath.h's style): NULL in each position in turn posts
    /// kQ3ErrorNULLParameter and returns NULL (kQ3Failure for a status, 0
    /// for a number), and the result pointed to keeps every byte.
    template <class R, class... A>
    void expectEachNullRejected(const char* name, R (*call)(A...), typename std::common_type<A>::type... args)
    {
        const std::tuple<A...> given(args...);
        auto* result = std::get<sizeof...(A) - 1>(given);
        std::vector<unsigned char> before(sizeof *result);
        std::memcpy(before.data(), result, before.size());
        for (std::size_t i = 0; i < sizeof...(A); ++i) {
            const R returned = callWithNullAt(call, given, i, std::index_sequence_for<A...>{});
            if constexpr (std::is_pointer<R>::value)
                EXPECT_EQ(returned, nullptr) << name << " with argument " << i << " NULL";
            else if constexpr (std::is_same<R, TQ3Status>::value)
                EXPECT_EQ(returned, kQ3Failure) << name << " with argument " << i << " NULL";
            else
                EXPECT_EQ(returned, R(0)) << name << " with argument " << i << " NULL";
            EXPECT_EQ(Q3Error_Get(nullptr), kQ3ErrorNULLParameter) << name << " with argument " << i << " NULL";
            consume(Kind::Error, kQ3ErrorNULLParameter, name, __FILE__, __LINE__);
        }
        EXPECT_EQ(std::memcmp(before.data(), result, before.size()), 0) << name << " changed its result";
    }

    static const char* kindName(Kind kind)
    {
        return kind == Kind::Error ? "error" : kind == Kind::Warning ? "warning" : "notice";
    }

private:
    template <class R, class... A, std::size_t... I>
    static R callWithNullAt(R (*call)(A...), const std::tuple<A...>& given, std::size_t nullAt,
                            std::index_sequence<I...>)
    {
        return call((I == nullAt ? A(nullptr) : std::get<I>(given))...);
    }

    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
    static std::vector<Posted>& posted()
    {
        static std::vector<Posted> list;
        return list;
    }
    static void record(Kind kind, long code, const char* message)
    {
        std::lock_guard<std::mutex> lock(mutex());
        posted().push_back({kind, code, message ? message : ""});
    }
    static void onError(TQ3Error, TQ3Error last, long) { record(Kind::Error, last, Q3Error_GetMessage()); }
    static void onWarning(TQ3Warning, TQ3Warning last, long)
    {
        record(Kind::Warning, last, Q3Warning_GetMessage());
    }
    static void onNotice(TQ3Notice, TQ3Notice last, long) { record(Kind::Notice, last, ""); }

    unsigned long m_liveAtStart = 0;
};

} // namespace q3test

/// Runs statement and consumes the error it must have posted; also checks
/// that Q3Error_Get reports the same code right after the call.
#define EXPECT_Q3_ERROR(statement, code)                                                      \
    do {                                                                                      \
        statement;                                                                            \
        EXPECT_EQ(Q3Error_Get(nullptr), (code)) << #statement;                                \
        consume(q3test::Kind::Error, (code), #statement, __FILE__, __LINE__);                 \
    } while (0)

#define EXPECT_Q3_WARNING(statement, code)                                                    \
    do {                                                                                      \
        statement;                                                                            \
        consume(q3test::Kind::Warning, (code), #statement, __FILE__, __LINE__);               \
    } while (0)

#define EXPECT_Q3_NOTICE(statement, code)                                                     \
    do {                                                                                      \
        statement;                                                                            \
        consume(q3test::Kind::Notice, (code), #statement, __FILE__, __LINE__);                \
    } while (0)

// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/ErrorManager.h"

#include "core/ThreadLocal.h"

#include <mutex>

namespace q3::errors {
namespace {

template <class Code>
struct Posted {
    Code first{};
    Code last{};
    std::string message;

    void post(Code code, const std::string& text)
    {
        if (first == Code{})
            first = code;
        last = code;
        message = text;
    }
};

struct ThreadState {
    Posted<TQ3Error> error;
    Posted<TQ3Warning> warning;
    Posted<TQ3Notice> notice;
};

// Still the thread's own after its thread_local objects are destroyed, for
// calls from atexit handlers and static destructors (core/ThreadLocal.h).
ThreadState& state()
{
    return threadLocal<ThreadState, ThreadState>();
}

template <class Method>
struct Callback {
    Method method = nullptr;
    long reference = 0;
};

std::mutex g_callbackMutex;
Callback<TQ3ErrorMethod> g_errorCallback;
Callback<TQ3WarningMethod> g_warningCallback;
Callback<TQ3NoticeMethod> g_noticeCallback;

template <class Method>
Callback<Method> snapshot(const Callback<Method>& callback)
{
    std::lock_guard<std::mutex> lock(g_callbackMutex);
    return callback;
}

template <class Code, class Method>
void postAndNotify(Posted<Code>& posted, const Callback<Method>& registered, Code code,
                   const std::string& message)
{
    posted.post(code, message);
    const Callback<Method> callback = snapshot(registered);
    if (callback.method != nullptr)
        callback.method(posted.first, posted.last, callback.reference);
}

} // namespace

void beginCall()
{
    state() = ThreadState{};
}

void postError(TQ3Error code, const std::string& message)
{
    postAndNotify(state().error, g_errorCallback, code, message);
}

void postWarning(TQ3Warning code, const std::string& message)
{
    postAndNotify(state().warning, g_warningCallback, code, message);
}

void postNotice(TQ3Notice code, const std::string& message)
{
    postAndNotify(state().notice, g_noticeCallback, code, message);
}

TQ3Error latestError(TQ3Error* first)
{
    if (first != nullptr)
        *first = state().error.first;
    return state().error.last;
}

TQ3Warning latestWarning(TQ3Warning* first)
{
    if (first != nullptr)
        *first = state().warning.first;
    return state().warning.last;
}

TQ3Notice latestNotice(TQ3Notice* first)
{
    if (first != nullptr)
        *first = state().notice.first;
    return state().notice.last;
}

const char* errorMessage()
{
    return state().error.message.c_str();
}

const char* warningMessage()
{
    return state().warning.message.c_str();
}

void registerErrorMethod(TQ3ErrorMethod method, long reference)
{
    std::lock_guard<std::mutex> lock(g_callbackMutex);
    g_errorCallback = {method, reference};
}

void registerWarningMethod(TQ3WarningMethod method, long reference)
{
    std::lock_guard<std::mutex> lock(g_callbackMutex);
    g_warningCallback = {method, reference};
}

void registerNoticeMethod(TQ3NoticeMethod method, long reference)
{
    std::lock_guard<std::mutex> lock(g_callbackMutex);
    g_noticeCallback = {method, reference};
}

} // namespace q3::errors

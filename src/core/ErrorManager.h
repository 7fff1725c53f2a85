// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DErrors.h"

#include <string>

/// The error manager: what each API call posted, per thread, and the
/// process-wide callbacks. An API call starts with beginCall(), which forgets
/// what the previous call on the same thread posted.
namespace q3::errors {

void beginCall();

void postError(TQ3Error code, const std::string& message);
void postWarning(TQ3Warning code, const std::string& message);
void postNotice(TQ3Notice code, const std::string& message);

TQ3Error latestError(TQ3Error* first);
TQ3Warning latestWarning(TQ3Warning* first);
TQ3Notice latestNotice(TQ3Notice* first);
const char* errorMessage();
const char* warningMessage();

void registerErrorMethod(TQ3ErrorMethod method, long reference);
void registerWarningMethod(TQ3WarningMethod method, long reference);
void registerNoticeMethod(TQ3NoticeMethod method, long reference);

} // namespace q3::errors

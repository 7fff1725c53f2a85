// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The error-manager calls neither clear what the previous call posted nor need
// Q3Initialize, so they do not go through api::guard.
#include "QD3DErrors.h"
#include "core/ErrorManager.h"

using namespace q3;

extern "C" {

TQ3Status Q3Error_Register(TQ3ErrorMethod errorPost, long reference)
{
    errors::registerErrorMethod(errorPost, reference);
    return kQ3Success;
}

TQ3Status Q3Warning_Register(TQ3WarningMethod warningPost, long reference)
{
    errors::registerWarningMethod(warningPost, reference);
    return kQ3Success;
}

TQ3Status Q3Notice_Register(TQ3NoticeMethod noticePost, long reference)
{
    errors::registerNoticeMethod(noticePost, reference);
    return kQ3Success;
}

TQ3Error Q3Error_Get(TQ3Error* firstError)
{
    return errors::latestError(firstError);
}

TQ3Boolean Q3Error_IsFatalError(TQ3Error error)
{
    return (error == kQ3ErrorInternalError || error == kQ3ErrorNoRecovery ||
            error == kQ3ErrorLastFatalError)
               ? kQ3True
               : kQ3False;
}

TQ3Warning Q3Warning_Get(TQ3Warning* firstWarning)
{
    return errors::latestWarning(firstWarning);
}

TQ3Notice Q3Notice_Get(TQ3Notice* firstNotice)
{
    return errors::latestNotice(firstNotice);
}

const char* Q3Error_GetMessage(void)
{
    return errors::errorMessage();
}

const char* Q3Warning_GetMessage(void)
{
    return errors::warningMessage();
}

} // extern "C"

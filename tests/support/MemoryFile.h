// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Writing a 3DMF file into memory storage through the public API, shared by
// the file tests (which check each step with GoogleTest) and the 3DMF fuzzer
// (which aborts on a failed step): no test framework here.

#include "QD3D.h"
#include "QD3DIO.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include <vector>

namespace q3test {

/// The bytes of a file written in `mode` into a new memory storage through
/// `view` by a writing loop whose every pass calls `submit(view)`. Each
/// step's outcome goes to `check(ok, what)`, which may count it or stop the
/// program.
template <class Submit, class Check>
std::vector<unsigned char> writeMemoryFileThrough(TQ3ViewObject view, TQ3FileMode mode, Submit&& submit,
                                                  Check&& check)
{
    std::vector<unsigned char> bytes;
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();
    check(Q3File_SetStorage(file, storage) == kQ3Success, "Q3File_SetStorage");
    check(Q3File_OpenWrite(file, mode) == kQ3Success, "Q3File_OpenWrite");
    check(Q3View_StartWriting(view, file) == kQ3Success, "Q3View_StartWriting");
    TQ3ViewStatus status;
    do {
        submit(view);
        status = Q3View_EndWriting(view);
    } while (status == kQ3ViewStatusRetraverse);
    check(status == kQ3ViewStatusDone, "Q3View_EndWriting");
    check(Q3File_Close(file) == kQ3Success, "Q3File_Close after writing");
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    check(Q3MemoryStorage_GetBuffer(storage, &buffer, &size, nullptr) == kQ3Success, "Q3MemoryStorage_GetBuffer");
    if (buffer != nullptr)
        bytes.assign(buffer, buffer + size);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return bytes;
}

/// The same through a new view.
template <class Submit, class Check>
std::vector<unsigned char> writeMemoryFile(TQ3FileMode mode, Submit&& submit, Check&& check)
{
    TQ3ViewObject view = Q3View_New();
    std::vector<unsigned char> bytes = writeMemoryFileThrough(view, mode, submit, check);
    Q3Object_Dispose(view);
    return bytes;
}

} // namespace q3test

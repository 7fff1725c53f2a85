// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DController.h"

#include "api/Entry.h"
#include "controller/Controller.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3ControllerStateObject Q3ControllerState_New(TQ3ControllerRef controllerRef)
{
    return guard(__func__, TQ3ControllerStateObject{nullptr}, [&]() -> TQ3ControllerStateObject {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        controllers::lookup(controllerRef, "controllerRef");
        return makeShared<ControllerState>(controllerRef).detach();
    });
}

TQ3Status Q3ControllerState_SaveAndReset(TQ3ControllerStateObject controllerStateObject)
{
    return guardStatus(__func__, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        lookup<ControllerState>(controllerStateObject, "controllerStateObject").saveAndReset();
    });
}

TQ3Status Q3ControllerState_Restore(TQ3ControllerStateObject controllerStateObject)
{
    return guardStatus(__func__, [&] {
        std::lock_guard<std::recursive_mutex> lock(controllerMutex());
        lookup<ControllerState>(controllerStateObject, "controllerStateObject").restore();
    });
}

} // extern "C"

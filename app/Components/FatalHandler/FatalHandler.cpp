// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  FatalHandler.cpp
// \brief  Stops the system on a FATAL event
// ======================================================================
#include "app/Components/FatalHandler/FatalHandler.hpp"
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>

namespace Kit {

FatalHandler::FatalHandler(const char* const compName) : FatalHandlerComponentBase(compName) {}

FatalHandler::~FatalHandler() {}

void FatalHandler::FatalReceive_handler(FwIndexType portNum, FwEventIdType Id) {
    (void)portNum;
    // Same line in both variants; the panic reports the faulting context
    printk("KIT FATAL event=0x%x\n", static_cast<unsigned int>(Id));
    k_panic();
}

}  // namespace Kit

// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  FatalHandler.hpp
// \brief  Stops the system on a FATAL event
// ======================================================================
#ifndef KIT_FATALHANDLER_HPP
#define KIT_FATALHANDLER_HPP

#include "app/Components/FatalHandler/FatalHandlerComponentAc.hpp"

namespace Kit {

class FatalHandler final : public FatalHandlerComponentBase {
  public:
    explicit FatalHandler(const char* const compName);
    ~FatalHandler();

  private:
    void FatalReceive_handler(FwIndexType portNum, FwEventIdType Id) override;
};

}  // namespace Kit

#endif

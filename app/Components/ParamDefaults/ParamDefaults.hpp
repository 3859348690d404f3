// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ParamDefaults.hpp
// \brief  Parameter reads where there is no parameter database
// ======================================================================
#ifndef KIT_PARAMDEFAULTS_HPP
#define KIT_PARAMDEFAULTS_HPP

#include "app/Components/ParamDefaults/ParamDefaultsComponentAc.hpp"

namespace Kit {

class ParamDefaults final : public ParamDefaultsComponentBase {
  public:
    explicit ParamDefaults(const char* const compName);
    ~ParamDefaults();

  private:
    Fw::ParamValid getPrm_handler(FwIndexType portNum, FwPrmIdType id, Fw::ParamBuffer& val) override;
};

}  // namespace Kit

#endif

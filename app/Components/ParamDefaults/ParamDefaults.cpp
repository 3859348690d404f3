// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ParamDefaults.cpp
// \brief  Parameter reads where there is no parameter database
// ======================================================================
#include "app/Components/ParamDefaults/ParamDefaults.hpp"

namespace Kit {

ParamDefaults::ParamDefaults(const char* const compName) : ParamDefaultsComponentBase(compName) {}

ParamDefaults::~ParamDefaults() {}

Fw::ParamValid ParamDefaults::getPrm_handler(FwIndexType portNum, FwPrmIdType id, Fw::ParamBuffer& val) {
    (void)portNum;
    (void)id;
    val.resetSer();
    return Fw::ParamValid::INVALID;
}

}  // namespace Kit

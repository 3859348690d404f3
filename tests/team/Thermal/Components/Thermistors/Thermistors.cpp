// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Thermistors.cpp
// \brief  50 Hz thermistor sampling of the heated zones
// ======================================================================
#include "Thermal/Components/Thermistors/Thermistors.hpp"
#include <Fw/Types/Assert.hpp>

namespace Thermal {

Thermistors::Thermistors(const char* const compName) : ThermistorsComponentBase(compName), m_zones(), m_samples(0) {
    for (Zone& zone : m_zones) {
        zone = {AMBIENT_MC, AMBIENT_MC, false};
    }
}

Thermistors::~Thermistors() {}

void Thermistors::schedIn_handler(FwIndexType portNum, U32 context) {
    (void)portNum;
    (void)context;
    for (Zone& zone : m_zones) {
        // The model: heat in while the heater is on, loss toward ambient
        zone.modelMc += (zone.heater ? HEATING_MC : 0) - (zone.modelMc - AMBIENT_MC) / LOSS_DIVISOR;
        // A first-order filter of FILTER_SAMPLES samples
        zone.filterMc += (zone.modelMc - zone.filterMc) / static_cast<I32>(FILTER_SAMPLES);
    }
    m_samples++;
    this->tlmWrite_Zone0(m_zones[0].filterMc);
    this->tlmWrite_Zone1(m_zones[1].filterMc);
    this->tlmWrite_Samples(m_samples);
}

I32 Thermistors::temperatureGet_handler(FwIndexType portNum, U8 zone) {
    (void)portNum;
    FW_ASSERT(zone < ZONES, zone);
    return m_zones[zone].filterMc;
}

void Thermistors::heaterIn_handler(FwIndexType portNum, U8 zone, bool heaterOn) {
    (void)portNum;
    FW_ASSERT(zone < ZONES, zone);
    m_zones[zone].heater = heaterOn;
}

}  // namespace Thermal

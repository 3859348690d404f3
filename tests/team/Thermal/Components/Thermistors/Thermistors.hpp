// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Thermistors.hpp
// \brief  50 Hz thermistor sampling of the heated zones
// ======================================================================
#ifndef THERMAL_THERMISTORS_HPP
#define THERMAL_THERMISTORS_HPP

#include "Thermal/Components/Ports/FppConstantsAc.hpp"
#include "Thermal/Components/Thermistors/ThermistorsComponentAc.hpp"

namespace Thermal {

class Thermistors final : public ThermistorsComponentBase {
  public:
    //! The heated zones (Ports.fpp); the telemetry has a channel per zone
    static constexpr U8 ZONES = zones;
    static_assert(ZONES == 2, "Thermistors.fpp has a channel for each of two zones");
    //! Where every zone starts, and where it settles without its heater
    static constexpr I32 AMBIENT_MC = 5000;
    //! What a heater adds per sample while on, and what a zone loses per
    //! sample per degree above ambient (1/LOSS_DIVISOR of the difference)
    static constexpr I32 HEATING_MC = 20;
    static constexpr I32 LOSS_DIVISOR = 512;
    //! Samples averaged (a power of two)
    static constexpr U32 FILTER_SAMPLES = 8;

    explicit Thermistors(const char* const compName);
    ~Thermistors();

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    I32 temperatureGet_handler(FwIndexType portNum, U8 zone) override;
    void heaterIn_handler(FwIndexType portNum, U8 zone, bool heaterOn) override;

    struct Zone {
        I32 modelMc;   //!< the zone's temperature in the model
        I32 filterMc;  //!< the filtered reading
        bool heater;
    };
    Zone m_zones[ZONES];
    U32 m_samples;
};

}  // namespace Thermal

#endif

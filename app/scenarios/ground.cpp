// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  ground.cpp
// \brief  The deployment serves the ground link, and nothing else
// ======================================================================
//
// No built-in command sequence: every command comes up the ground link
// (fprime-gds, `kit gds`, the integration suite in tests/integration), and
// the run never ends (a tick count of 0), as a flight deployment's does.

#include "app/scenarios/Scenario.hpp"
#include "app/src/Report.hpp"
#include "app/src/Session.hpp"

namespace Kit {
namespace Scenario {

bool run(const Context& context) {
    (void)context;
    Report::linkReady();
    Session::run(0);
    return true;
}

}  // namespace Scenario
}  // namespace Kit

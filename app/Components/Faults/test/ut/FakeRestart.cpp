// SPDX-License-Identifier: Apache-2.0
// The host tests' restart: counted, nothing restarts
#include "app/Components/Faults/test/ut/FakeRestart.hpp"

namespace Kit {
namespace Restart {

U32 FakeRestart::restarts = 0;

void warm() {
    FakeRestart::restarts++;
}

}  // namespace Restart
}  // namespace Kit

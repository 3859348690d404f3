// SPDX-License-Identifier: Apache-2.0
// The host tests' restart: counted, nothing restarts
#ifndef KIT_FAKERESTART_HPP
#define KIT_FAKERESTART_HPP

#include <Fw/FPrimeBasicTypes.hpp>
#include "app/Components/Faults/Restart.hpp"

namespace Kit {
namespace Restart {

struct FakeRestart {
    static U32 restarts;  //!< warm() calls so far
};

}  // namespace Restart
}  // namespace Kit

#endif

// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Fatal.hpp
// \brief  Where every fatal path ends (k_sys_fatal_error_handler, Fatal.cpp)
// ======================================================================
#ifndef KIT_FATAL_HPP
#define KIT_FATAL_HPP

namespace Kit {
namespace Fatal {

//! The scenario is about to inject a fatal fault on purpose: a fatal error
//! with this reason (K_ERR_*) is then reported expected=yes, without
//! twister's failure marker, so the scenario's own patterns decide. Any other
//! fatal error still fails the run at once.
void expect(unsigned int reason);

//! Report a fatal error (reason: K_ERR_*) and stop: the end of every fatal
//! path, Zephyr's (k_sys_fatal_error_handler) and the kit's own detectors'
[[noreturn]] void halt(unsigned int reason);

}  // namespace Fatal
}  // namespace Kit

#endif

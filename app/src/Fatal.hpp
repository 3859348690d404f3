// ======================================================================
// \title  Fatal.hpp
// \brief  Where every fatal path ends (k_sys_fatal_error_handler, Fatal.cpp)
// ======================================================================
#ifndef KIT_FATAL_HPP
#define KIT_FATAL_HPP

namespace Kit {
namespace Fatal {

//! The scenario is about to inject a fatal fault on purpose: the fatal
//! report then says expected=yes and leaves out twister's failure marker,
//! so the scenario's own patterns decide. Any other fatal fails the run.
void expect();

}  // namespace Fatal
}  // namespace Kit

#endif

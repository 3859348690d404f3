// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  rtos/AssertReport.hpp
// \brief  An F´ assert's report, on a thread of its own
// ======================================================================
#ifndef KIT_ASSERTREPORT_HPP
#define KIT_ASSERTREPORT_HPP

namespace Kit {
namespace AssertReport {

//! After the deployment's objects are built (its assert hook registered),
//! before its tasks start: from here on, an assert raised on any thread is
//! reported on the report thread's stack (rtos/AssertReport.cpp)
void start();

}  // namespace AssertReport
}  // namespace Kit

#endif

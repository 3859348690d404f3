// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  exceptions_off.cpp
// \brief  The C++ runtime's exception allocator, in a build without exceptions
//
// F´ and the kit build with exceptions off (CONFIG_CPP_EXCEPTIONS=n), yet
// the toolchain's libstdc++ still links its exception allocator (eh_alloc.o):
// the guard of every function-local static (__cxa_guard_acquire, guard.o)
// can throw recursive_init_error. That allocator's constructor mallocs an
// emergency pool at start-up, 2528 B of the C heap on a 32-bit part without
// gthreads (GCC 12: 4 objects of 512 B and their headers), for exceptions
// no code here can catch. These four definitions take its place, so the
// linker never pulls eh_alloc.o: a throw, which could only end in
// std::terminate() here, halts at once with one line saying why (Zephyr's
// k_panic: the kit's fatal report names it kernel_panic). Built only where
// exceptions are off and the C++ library is libstdc++ (CMakeLists.txt).
// ======================================================================
#include <zephyr/kernel.h>
#include <zephyr/sys/printk.h>
#include <zephyr/toolchain.h>

#include <cstddef>

namespace {

[[noreturn]] void exceptionsAreOff() {
    printk("C++ exception thrown in a build without exceptions (CONFIG_CPP_EXCEPTIONS=n)\n");
    k_panic();
    CODE_UNREACHABLE;
}

}  // namespace

// The C++ ABI's names (cxxabi.h), declared here with untyped pointers: C
// linkage, so only the names have to match
extern "C" {

void* __cxa_allocate_exception(size_t size) noexcept {
    (void)size;
    exceptionsAreOff();
}

void __cxa_free_exception(void* thrown) noexcept {
    (void)thrown;
    exceptionsAreOff();
}

void* __cxa_allocate_dependent_exception() noexcept {
    exceptionsAreOff();
}

void __cxa_free_dependent_exception(void* dependent) noexcept {
    (void)dependent;
    exceptionsAreOff();
}

}  // extern "C"

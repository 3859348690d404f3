# SPDX-License-Identifier: Apache-2.0
# Source this to use west, twister and fprime-util by hand in this clone:
#   . scripts/env.sh
# Activates the kit's venv and selects Debian's arm-none-eabi toolchain
# (Zephyr's gnuarmemb variant) unless a Zephyr SDK is already selected.
_kit_root=$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)
if [ ! -x "$_kit_root/.venv/bin/west" ]; then
  echo "kit: not provisioned yet: run scripts/setup.sh first" >&2
  return 1 2>/dev/null || exit 1
fi
export VIRTUAL_ENV="$_kit_root/.venv"
case ":$PATH:" in *":$VIRTUAL_ENV/bin:"*) ;; *) export PATH="$VIRTUAL_ENV/bin:$PATH" ;; esac
export ZEPHYR_BASE="$_kit_root/deps/zephyr"
# ccache hits across build folders only with paths hashed relative to the clone
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$_kit_root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
if [ -z "${ZEPHYR_TOOLCHAIN_VARIANT:-}" ] && [ -z "${ZEPHYR_SDK_INSTALL_DIR:-}" ]; then
  export ZEPHYR_TOOLCHAIN_VARIANT=gnuarmemb
  _kit_gcc=$(command -v arm-none-eabi-gcc || true)
  export GNUARMEMB_TOOLCHAIN_PATH="${_kit_gcc%/bin/arm-none-eabi-gcc}"
  [ -n "$_kit_gcc" ] || echo "kit: arm-none-eabi-gcc not found: run scripts/setup.sh" >&2
  unset _kit_gcc
fi
unset _kit_root

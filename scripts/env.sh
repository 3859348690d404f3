# SPDX-License-Identifier: Apache-2.0
# Source this to use west, twister and fprime-util by hand in this clone:
#   . scripts/env.sh
# Activates the kit's venv and selects Debian's arm-none-eabi toolchain
# (Zephyr's gnuarmemb variant) unless a Zephyr SDK is already selected
# (app/toolchain.cmake).
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
# The toolchain: app/toolchain.cmake decides (the rule every build applies),
# printing NAME=value lines to export, none when one is chosen already
if _kit_choice=$("$VIRTUAL_ENV/bin/cmake" -P "$_kit_root/app/toolchain.cmake"); then
  while IFS='=' read -r _kit_name _kit_value; do
    [ -z "$_kit_name" ] || export "$_kit_name=$_kit_value"
  done <<EOF
$_kit_choice
EOF
else
  echo "kit: no toolchain chosen (above): run scripts/setup.sh" >&2
fi
unset _kit_root _kit_choice _kit_name _kit_value

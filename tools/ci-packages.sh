# Sourced by the CI steps (tools/ci.d/*.sh): what a step needs from Debian,
# found missing and installed in one place.

# The Debian packages of the Cortex-M toolchain and QEMU that are missing.
arm_packages_missing() {
    command -v arm-none-eabi-gcc >/dev/null 2>&1 || printf ' gcc-arm-none-eabi'
    [ -e /usr/lib/arm-none-eabi/newlib/thumb/v7e-m+fp/hard/libc_nano.a ] ||
        printf ' libnewlib-arm-none-eabi'
    command -v qemu-system-arm >/dev/null 2>&1 || printf ' qemu-system-arm'
}

# install_packages STEP PACKAGES...: apt-get the packages given, if any.
install_packages() {
    step=$1
    shift
    [ "$#" -gt 0 ] || return 0
    echo "$step: installing $*"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"
}

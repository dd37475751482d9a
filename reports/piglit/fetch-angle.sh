#!/bin/sh
# ANGLE as shared libraries, for piglit (run.sh, implementations angle-vulkan-*). Debian's chromium
# links ANGLE into its executable (chromium-common's libEGL.so / libGLESv2.so are 3.6 KB stubs that
# export no EGL or GL function), so piglit cannot load the ANGLE of `webgl:*`. The nearest ANGLE
# build the package registries have: the CEF runtime in the PyPI wheel cef-capi-py 131.3.5 (CEF
# 131.3.5+g573cec5+chromium-131.0.6778.205; libGLESv2.so says "2.1.24078 git hash: ac6cda4cbd71").
# It ships the Vulkan loader ANGLE was built with (libvulkan.so.1): with Debian's loader
# (1.3.239) ANGLE's Vulkan display fails "Internal Vulkan error (-3)" in vk_renderer.cpp
# initialize, with CEF's it initializes.
# Writes libEGL.so, libGLESv2.so, libvulkan.so.1 to $SHADOWCHECK_ANGLE_DIR, default
# ${XDG_CACHE_HOME:-~/.cache}/shadowcheck/angle-cef_capi_py-131.3.5. Needs pip and unzip.
set -e
DIR=${SHADOWCHECK_ANGLE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowcheck/angle-cef_capi_py-131.3.5}
T=$(mktemp -d)
pip download --no-deps --only-binary=:all: --platform manylinux2014_x86_64 -d "$T" 'cef-capi-py==131.3.5'
mkdir -p "$DIR"
unzip -o -j -q "$T"/cef_capi_py-131.3.5-*.whl 'cef_capi/runtime/libEGL.so' \
  'cef_capi/runtime/libGLESv2.so' 'cef_capi/runtime/libvulkan.so.1' 'cef_capi/version.py' -d "$DIR"
rm -rf "$T"
grep '^CEF_VERSION =' "$DIR/version.py"
ls -l "$DIR"

# Sourced by run.sh and run_repro.sh: the Chromium flags and environment of each configuration.
# backend_setup CONFIG sets the arrays `flags` (run_webgl_cts.js --flag=... arguments) and `envs`
# (VAR=value, for env(1)); returns 2 for an unknown CONFIG.
common=(--flag=--headless --flag=--no-sandbox --flag=--disable-quic --flag=--no-first-run
        --flag=--disable-background-networking --flag=--disable-component-update
        --flag=--disable-sync --flag=--disable-extensions)
backend_setup() {
  envs=()
  case "$1" in
    swiftshader)
      flags=("${common[@]}" --flag=--use-angle=swiftshader --flag=--enable-unsafe-swiftshader
             --flag=--disable-gpu) ;;
    gles-llvmpipe)
      flags=("${common[@]}" --flag=--use-angle=gles-egl --flag=--ignore-gpu-blocklist)
      envs=(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe EGL_PLATFORM=surfaceless) ;;
    vulkan-lavapipe)
      flags=("${common[@]}" --flag=--use-angle=vulkan --flag=--ignore-gpu-blocklist
             --flag=--disable-gpu-driver-bug-workarounds)
      envs=(VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json) ;;
    *) echo "unknown config $1" >&2; return 2 ;;
  esac
}

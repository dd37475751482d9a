#!/bin/sh
# Standalone Vulkan reproducer: cube map edge handling of a LINEAR depth-compare lookup in a compute
# shader vs. a fragment shader, on SwiftShader (Chromium's) and lavapipe, each variant under the
# Khronos validation layer. Writes output.txt. Debian 12:
#   apt-get install -y gcc libvulkan-dev glslang-tools libvulkan1 mesa-vulkan-drivers vulkan-validationlayers
cd "$(dirname "$0")" || exit 2
for s in vert frag comp; do glslangValidator --quiet -V -S $s -o $s.spv $s.glsl || exit 2; done
glslangValidator --quiet -V -S frag -DNOCOMPARE -o frag_nc.spv frag.glsl || exit 2
glslangValidator --quiet -V -S comp -DNOCOMPARE -o comp_nc.spv comp.glsl || exit 2
gcc -std=c99 -O1 -Wall -o repro repro.c -lvulkan -lm || exit 2
SWS=/usr/lib/chromium/vk_swiftshader_icd.json
LVP=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
run() { # driver-name icd args...
  name=$1 icd=$2; shift 2
  echo "== $name: ./repro $*"
  # The loader's "(general message ...)" notes that VK_INSTANCE_LAYERS added the layer are dropped.
  env VK_ICD_FILENAMES=$icd VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation ./repro "$@" 2>&1 | grep -v '^(general message'
}
{
  for d in "swiftshader $SWS" "lavapipe $LVP"; do
    set -- $d
    for v in "--runs=5" "--repeat" "--corner" "--nearest" "--levels=1" "--nocompare" "--nocompare --corner" \
             "--frag-first" "--runs=3 --repeat --corner --levels=1"; do
      run "$1" "$2" $v
      echo "exit status $(env VK_ICD_FILENAMES=$2 ./repro $v >/dev/null 2>&1; echo $?)"
      echo
    done
  done
  echo "== swiftshader: the base variant in 5 separate processes (first compute result of each)"
  for i in 1 2 3 4 5; do
    env VK_ICD_FILENAMES=$SWS ./repro | grep '^compute #1 '
  done
} > output.txt 2>&1
cat output.txt

# Every installed header compiles on its own, in a translation unit that
# includes nothing else, with compilers other than the one that built the
# library: gcc and clang as strict C99 (-pedantic -Werror), gcc with
# __GNUC__ undefined (the branch a non-GNU compiler takes; the generic
# headers: the ISA headers' intrinsics need a GNU compiler's headers), tcc
# and pcc (non-GNU C compilers), and g++ as C++11 and C++17 (-pedantic
# -Wall -Wextra -Werror; C++11 has no hex-float literals, so the headers
# spell their powers of two as exact decimals).  The port headers that need ISA flags get them (x86 only; the
# NEON and RISC-V headers are compiled by their suites; the Helium ones,
# f32 and binary16, also here with the Cortex-M55's gcc, clang and g++).  A
# compiler that is missing is named and its checks skipped.
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL headers: $*"; }
have() { command -v "$1" > /dev/null 2>&1; }
dir=build/headers
mkdir -p $dir
x86=
case "$(${CC:-cc} -dumpmachine)" in x86_64*) x86=1 ;; esac
# header FLAGS: the ISA flags a header needs (empty: none), or "skip"
isa() {
    case $1 in
    facet/sse2.h) [ -n "$x86" ] && echo "-msse2" || echo skip ;;
    facet/avx2.h) [ -n "$x86" ] && echo "-mavx2 -mfma" || echo skip ;;
    facet/avx512.h) [ -n "$x86" ] && echo "-mavx512f -mavx2 -mfma" || echo skip ;;
    facet/avx512fp16.h) [ -n "$x86" ] && echo "-mavx512fp16 -mavx512bw -mavx512vl -mavx512f" || echo skip ;;
    facet/neon.h | facet/neonfp16.h | facet/helium.h | facet/heliumfp16.h | facet/rvv.h | facet/rvvfp16.h) echo skip ;;
    *) echo "" ;;
    esac
}
headers="facet.h $(cd include && ls facet/*.h)"
try() { # try LABEL HEADER COMPILER ARGS...: compiles a TU that includes HEADER
    label=$1 h=$2
    shift 2
    ext=c
    case $label in c++*) ext=cc ;; esac
    src=$dir/$(echo "$h" | tr '/.' '__').$ext
    printf '#include <%s>\nint facet_header_probe_(void);\nint facet_header_probe_(void) { return 0; }\n' "$h" > $src
    if out=$("$@" -Iinclude -c $src -o $dir/probe.o 2>&1); then ok
    else bad "$label: $h does not compile: $(printf '%s' "$out" | head -n 3 | tr '\n' ' ')"; fi
}
for h in $headers; do
    f=$(isa $h)
    [ "$f" = skip ] && continue
    try gcc-c99 $h gcc -std=c99 -pedantic -Wall -Wextra -Werror $f
    [ -z "$f" ] && try gcc-no-gnuc $h gcc -std=c99 -U__GNUC__ -Wall -Wextra -Werror
    if have clang; then try clang-c99 $h clang -std=c99 -pedantic -Wall -Wextra -Werror $f; fi
    if have g++; then
        try c++11 $h g++ -std=c++11 -pedantic -Wall -Wextra -Werror $f
        try c++17 $h g++ -std=c++17 -pedantic -Wall -Wextra -Werror $f
    fi
    # tcc and pcc take no ISA flags: the generic headers only
    [ -n "$f" ] && continue
    if have tcc; then try tcc $h tcc -Wall -Werror; fi
    if have pcc; then try pcc $h pcc; fi
done
# C++ users build with -Wold-style-cast: every header is clean under it (a
# conversion in a header is FACET_CAST, facet/common.h), on x86 with g++
# and, for the Arm port headers, with arm-none-eabi-g++ (Helium on M55,
# NEON on an A53 in A32) where it is installed, and clang++ for aarch64
# (neonfp16)
for h in $headers; do
    f=$(isa $h)
    [ "$f" = skip ] && continue
    if have g++; then try c++17-old-style-cast $h g++ -std=c++17 -Wall -Wextra -Wold-style-cast -Werror $f; fi
done
if have arm-none-eabi-g++; then
    for h in facet/helium.h facet/heliumfp16.h; do
        try c++17-old-style-cast $h arm-none-eabi-g++ -std=c++17 -Wall -Wextra -Wold-style-cast -Werror \
            -mcpu=cortex-m55 -mfloat-abi=hard -mthumb
    done
    try c++17-old-style-cast facet/neon.h arm-none-eabi-g++ -std=c++17 -Wall -Wextra -Wold-style-cast -Werror \
        -mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard -marm
fi
# the aarch64 binary16 header (no aarch64 g++ here): clang++ for aarch64
# with the cross libc's headers
if have clang++ && [ -d /usr/aarch64-linux-gnu/include ]; then
    for std in c++11 c++17; do
        try $std-old-style-cast facet/neonfp16.h clang++ --target=aarch64-linux-gnu -march=armv8.2-a+fp16 \
            -isystem /usr/aarch64-linux-gnu/include -std=$std -pedantic -Wall -Wextra -Wold-style-cast -Werror
    done
fi
# the Helium headers (f32 and binary16) with the Cortex-M55's compilers:
# arm-none-eabi-gcc and clang as strict C99, arm-none-eabi-g++ as C++11 and
# C++17 (-pedantic); the generic compilers cannot take MVE intrinsics
m55="-mcpu=cortex-m55 -mfloat-abi=hard -mthumb"
for h in facet/helium.h facet/heliumfp16.h; do
    if have arm-none-eabi-gcc; then
        try gcc-c99-m55 $h arm-none-eabi-gcc -std=c99 -pedantic -Wall -Wextra -Werror $m55
        if have clang; then
            try clang-c99-m55 $h clang --target=arm-none-eabi -fshort-enums \
                -isystem "$(dirname "$(arm-none-eabi-gcc -print-file-name=libc.a)")/../include" \
                -std=c99 -pedantic -Wall -Wextra -Werror $m55
        fi
    fi
    if have arm-none-eabi-g++; then
        try c++11-m55 $h arm-none-eabi-g++ -std=c++11 -pedantic -Wall -Wextra -Werror $m55
        try c++17-m55 $h arm-none-eabi-g++ -std=c++17 -pedantic -Wall -Wextra -Werror $m55
    fi
done
for c in clang g++ tcc pcc; do
    if ! have $c; then
        echo "SKIP headers: $c not installed (apt-get install $c)"
        skip=$((skip + 1))
    fi
done
echo "headers: $pass passed, $fail failed, $skip skipped"

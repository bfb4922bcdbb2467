# Compiler flags of the sanitizer builds (sourced by sanitize.sh and fuzz.sh, so both build the same objects).
# AddressSanitizer, and UndefinedBehaviorSanitizer without the checks whose faults ASan already reports at
# the access: null, alignment (x86 loads tolerate it; Eigen asserts its own), object-size, pointer-overflow,
# function, nonnull-attribute and returns-nonnull-attribute. Measured on synthesis_paper9.cpp (clang 14, -O1):
# all of -fsanitize=undefined 73 s, this set 38-40 s, ASan alone 38 s; the whole sanitizer build
# took 2492 CPU-s with all of them.
sanitizer_checks="address,undefined"
sanitizer_skipped="alignment,null,object-size,pointer-overflow,function,nonnull-attribute,returns-nonnull-attribute"
sanitizer_cxx_flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=$sanitizer_checks -fno-sanitize=$sanitizer_skipped -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
sanitizer_link_flags="-fsanitize=$sanitizer_checks"

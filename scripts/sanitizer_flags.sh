# Compiler flags of the sanitizer builds, sourced by sanitize.sh and fuzz.sh so that both build the same objects.
# AddressSanitizer, and UndefinedBehaviorSanitizer without the checks whose faults ASan reports at the
# access itself (null, object-size, pointer-overflow) and three that guard against faults of kinds this code
# does not have: alignment (x86 loads tolerate it; Eigen asserts its own in this build), function (calls
# through a function pointer of another type) and the nonnull attributes. Those seven doubled the compile
# time: synthesis_paper9.cpp took 73 s with all of -fsanitize=undefined, 38-40 s without them (ASan alone
# 38 s); the whole sanitizer build 2492 CPU-s, then 1711.
sanitizer_checks="address,undefined"
sanitizer_skipped="alignment,null,object-size,pointer-overflow,function,nonnull-attribute,returns-nonnull-attribute"
sanitizer_cxx_flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=$sanitizer_checks -fno-sanitize=$sanitizer_skipped -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
sanitizer_link_flags="-fsanitize=$sanitizer_checks"

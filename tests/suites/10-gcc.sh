# The library and every test, built with the default compiler at -O2.
. tests/lib/suite_lib.sh
run_build_and_tests build gcc "${CC:-cc}" "-O2 -g"

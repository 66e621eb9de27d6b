#!/usr/bin/env python3
"""A CLI test that asserts an exit status ('test $? -eq 2') and also has a
PASS_REGULAR_EXPRESSION would never fail on the status: CTest ignores the exit code of a test
with a pass regex. Such a test must print the check's failure and fail on it with
FAIL_REGULAR_EXPRESSION. This scan of tests/CMakeLists.txt keeps that so."""
import re
import sys

text = open(sys.argv[1], encoding="utf-8").read()
commands = dict(re.findall(r'add_test\(NAME (\S+) COMMAND (.*)\)\n', text))
properties = {}
for name, props in re.findall(r'set_tests_properties\((\S+) PROPERTIES (.*)\)\n', text):
    properties[name] = properties.get(name, "") + props
bad = []
checked = 0
for name, command in commands.items():
    if not re.search(r'test \$(\?|rc) -(eq|ne|gt|lt)', command):
        continue
    props = properties.get(name, "")
    if "PASS_REGULAR_EXPRESSION" not in props:
        continue
    checked += 1
    if "|| echo hlr-test: the exit status check failed" not in command or \
            'FAIL_REGULAR_EXPRESSION "the exit status check failed"' not in props:
        bad.append(name)
print(f"{checked} tests assert an exit status next to a pass regex")
for name in bad:
    print(f"{name}: its exit status check cannot fail (add '|| echo hlr-test: the exit status check failed' "
          "and FAIL_REGULAR_EXPRESSION \"the exit status check failed\")")
sys.exit(1 if bad or checked == 0 else 0)

#!/usr/bin/env python3
"""check_json.py FILE COND... : FILE holds one JSON object (pe --json); each COND is
KEY OP VALUE with OP among == != >= <= > < and VALUE a JSON literal (true, 0, "OK")
or the name of another key of the object (energy_after<energy_before).
Exits 1 if the file is not exactly one JSON object or a condition fails."""
import json, operator, re, sys

OPS = [("==", operator.eq), ("!=", operator.ne), (">=", operator.ge), ("<=", operator.le),
       (">", operator.gt), ("<", operator.lt)]

def main():
    text = open(sys.argv[1]).read()
    obj = json.loads(text)  # raises on anything but one JSON value
    if not isinstance(obj, dict):
        print("not a JSON object"); return 1
    ok = True
    for cond in sys.argv[2:]:
        for sym, op in OPS:
            m = re.match(r"^(\w+)" + re.escape(sym) + r"(.+)$", cond)
            if m:
                key, rhs = m.group(1), m.group(2)
                value = obj[rhs] if re.match(r"^[A-Za-z_]\w*$", rhs) and rhs not in ("true", "false", "null") and rhs in obj \
                    else json.loads(rhs)
                if key not in obj:
                    print("missing key:", key); ok = False
                elif type(obj[key]) is bool and type(value) is not bool or not op(obj[key], value):
                    print("failed: %s (value %r)" % (cond, obj[key])); ok = False
                else:
                    print("ok: %s" % cond)
                break
        else:
            print("bad condition:", cond); ok = False
    return 0 if ok else 1

if __name__ == "__main__":
    sys.exit(main())

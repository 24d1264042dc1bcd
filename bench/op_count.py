#!/usr/bin/env python3
"""One operation counter for eomgen's and SymPy's emitted C: a small tokenizer over the statements.

Usage: op_count.py HEADER [FUNCTION]   prints {"add", "mul", "div", "call", "total"} as JSON
  eomgen header: FUNCTION (default `dynamics`) is the static member function whose body is counted;
  SymPy header (bench/sympy_pendulum.py): the text between `// BEGIN BODY` and `// END BODY`.

Rules, the same as eomgen's OpCount (generator/codegen/cpp_emitter.hpp):
  binary + and -, and unary minus: one addition each; *: one multiplication; /: one division;
  a call such as sin(x): one function call; pow(x, k) with an integer literal k: |k|-1 multiplications
  (and one division when k < 0), as the compiler emits for k = 2 and as eomgen writes it;
  Scalar(3) and 3.0 are literals; q_(0), M_(1, 2), p_.m (names ending in `_`, and member access) are reads.
Statements that only read inputs (`const Scalar m1 = p_.m1;`) contain no operators and count 0.
"""
import json
import re
import sys

TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?[LlFf]?)|(?P<id>[A-Za-z_][A-Za-z0-9_]*)"
                   r"|(?P<op>[-+*/(),.;=\[\]]))")


def tokens(text):
    pos = 0
    out = []
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m or m.end() == pos:
            if text[pos:].strip() == "":
                break
            raise ValueError(f"cannot tokenize at: {text[pos:pos + 40]!r}")
        pos = m.end()
        kind = m.lastgroup
        out.append((kind, m.group(kind)))
    return out


def count_expression(toks, counts):
    """Counts one right-hand side, given as tokens."""
    prev = None  # kind of the previous meaningful token: 'value', 'op', or None at the start
    i = 0
    while i < len(toks):
        kind, text = toks[i]
        if kind == "num":
            prev = "value"
        elif kind == "id":
            nxt = toks[i + 1][1] if i + 1 < len(toks) else None
            if nxt == "(" and text == "Scalar":  # a literal Scalar(3) or Scalar(1.5L)
                depth, j = 0, i + 1
                while True:
                    if toks[j][1] == "(":
                        depth += 1
                    elif toks[j][1] == ")":
                        depth -= 1
                        if depth == 0:
                            break
                    j += 1
                i = j
                prev = "value"
            elif nxt == "(" and text.endswith("_"):  # q_(0): an element read
                prev = "id_call"
            elif nxt == "(" and text == "pow":
                # pow(base, k): find the last top-level argument
                depth, j, comma = 0, i + 1, None
                while True:
                    t = toks[j][1]
                    if t == "(":
                        depth += 1
                    elif t == ")":
                        depth -= 1
                        if depth == 0:
                            break
                    elif t == "," and depth == 1:
                        comma = j
                    j += 1
                expo = toks[comma + 1:j]
                sign = -1 if expo and expo[0][1] == "-" else 1
                digits = expo[1:] if sign < 0 else expo
                if len(digits) == 1 and digits[0][0] == "num" and re.fullmatch(r"\d+(\.0*)?", digits[0][1]):
                    k = int(float(digits[0][1]))
                    counts["mul"] += max(k - 1, 0)
                    if sign < 0:
                        counts["div"] += 1
                    # count the base, then skip past the exponent
                    count_expression(toks[i + 2:comma], counts)
                    i = j
                    prev = "value"
                else:
                    counts["call"] += 1
                    prev = "id_call"
            elif nxt == "(":
                counts["call"] += 1
                prev = "id_call"
            else:
                prev = "value"
        elif kind == "op":
            if text in "+-":
                unary = prev in (None, "op", "open")
                if text == "-" or not unary:
                    counts["add"] += 1
                prev = "op"
            elif text in "*/":
                counts["mul" if text == "*" else "div"] += 1
                prev = "op"
            elif text in "(,":
                prev = "open"
            elif text == ")":
                prev = "value"
            elif text in ".[]":
                prev = "value" if text == "]" else "op_access"
        i += 1


def count_statements(statements):
    counts = {"add": 0, "mul": 0, "div": 0, "call": 0}
    for s in statements:
        s = s.strip()
        if not s or s.startswith("//") or s.startswith("using ") or s.startswith("static_cast<void>") \
                or s.startswith("(void)"):
            continue
        if s.startswith("return "):
            rhs = s[len("return "):]
        else:
            eq = s.find("=")
            if eq < 0:
                continue
            rhs = s[eq + 1:]
        count_expression(tokens(rhs.rstrip(";")), counts)
    counts["total"] = counts["add"] + counts["mul"] + counts["div"] + counts["call"]
    return counts


def body_statements(text, function="dynamics"):
    if "// BEGIN BODY" in text:
        body = text.split("// BEGIN BODY", 1)[1].split("// END BODY", 1)[0]
        return body.splitlines()
    m = re.search(r"static \w+ " + re.escape(function) + r"\(", text)
    if not m:
        raise ValueError(f"no function {function}")
    start = text.index("{", m.end())
    end = text.index("\n    }\n", start)
    return text[start + 1:end].splitlines()


def count_file(path, function="dynamics"):
    with open(path) as fh:
        return count_statements(body_statements(fh.read(), function))


if __name__ == "__main__":
    print(json.dumps(count_file(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "dynamics")))

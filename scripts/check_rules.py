#!/usr/bin/env python3
"""The house rules that check themselves (ctest -L rules): no function over 100 lines outside proof checks
and test tables, includes only down the folders' order (docs/layout.md), clang-format's layout, and no CLI
flag in the libraries' message text (numeric/io/option_words.hpp names options in each front end's words).

Usage: check_rules.py [--lengths] [--includes] [--format] [--flags] [--list-long N]   (no option: all four)
Exit 1 naming every breach, one per line: file:line: the rule and what breaks it.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MAX_LINES = 100

# The folders' order (docs/layout.md): a folder includes only folders before it (and itself).
# Inside numeric/, the role folders from the ground up; a role folder not listed is a breach until it is
# given its place here and in docs/layout.md.
NUMERIC_ORDER = ["io", "model", "program", "criteria", "polish", "synthesis", "certify", "region", "calibration",
                 "gyro", "thermal", "bench", "export"]
# The top-level libraries, then the front ends; consumers may include any library, never each other.
LIBRARY_ORDER = ["numeric", "symbolic", "plots", "commands", "experiments"]
CONSUMERS = {"tests", "python", "bench", "proofs", "web"}  # web: the page's WebAssembly core and its binding
EMBEDDED = {"embedded", "scalcal"}  # the C library and its include folder: self-contained

# Function length: sources of the libraries and front ends. Proof checks and tests hold long tables of
# cases by design (the exception); embedded/ is C held to the same rule.
LENGTH_ROOTS = ["numeric", "symbolic", "plots", "commands", "experiments", "python", "embedded/src",
                "embedded/include", "bench", "web/wasm"]
SOURCE = re.compile(r".*\.(cpp|hpp|h|c|cc)$")
CONTROL = re.compile(r"^(if|for|while|switch|catch|do|else|try|return|namespace|class|struct|enum|union|"
                     r"extern|template\s*<[^>]*>\s*(class|struct))\b")


def tracked_sources():
    return sorted(f for f in tracked_files() if SOURCE.match(f))


def tracked_files():
    try:
        out = subprocess.check_output(["git", "ls-files"], cwd=ROOT, text=True, stderr=subprocess.DEVNULL).split()
    except (OSError, subprocess.CalledProcessError):  # a tree without git (an unpacked source archive)
        out = []
        for d, dirs, names in os.walk(ROOT):
            dirs[:] = [x for x in dirs if not x.startswith((".", "build")) and x != "node_modules"]
            out += [os.path.relpath(os.path.join(d, n), ROOT) for n in names]
    return sorted(out)


def strip_code(text):
    """Comments and string/char literals blanked (newlines kept), so braces and keywords are the code's."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):  # raw string R"delim( ... )delim"
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and (text[i - 1].isalnum()):  # a digit separator, 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def is_function_header(header):
    """The code between the previous ; { } and a brace: a function's signature (not a control statement,
    a class, a namespace, an initialiser or a lambda's)."""
    h = " ".join(header.split())
    h = re.sub(r"^#.*$", "", h).strip()
    if not h or ")" not in h:
        return False
    if CONTROL.match(h) or re.search(r"\b(class|struct|namespace|enum|union)\b[^()]*$", h):
        return False
    # An initialiser: '=' outside parentheses (default arguments sit inside them; operator= is a name).
    depth, flat = 0, re.sub(r"operator\s*[^\s(]+\s*\(", "operator(", h)
    for ch in flat:
        depth += ch == "("
        depth -= ch == ")"
        if ch == "=" and depth == 0:
            return False
    return not h.endswith("]") and "](" not in h.split(")")[-1]


def long_functions(path):
    return long_functions_in(open(os.path.join(ROOT, path), encoding="utf-8", errors="replace").read())


def long_functions_in(text):
    """(first line, name, lines) of every function in the text longer than MAX_LINES."""
    code = strip_code(text)
    found, depth, in_function, start_line, start_depth = [], 0, False, 0, 0
    last = 0  # index after the last ; { } at any depth
    line_of = lambda k: code.count("\n", 0, k) + 1
    k = -1
    while k + 1 < len(code):
        k += 1
        ch = code[k]
        if ch == "{" and code.count("(", last, k) > code.count(")", last, k):
            # A braced value inside parentheses (a default argument `= {}`, a call's `{a, b}`): part of
            # the text around it, not a block.
            inner = 0
            while k < len(code):
                inner += (code[k] == "{") - (code[k] == "}")
                if inner == 0:
                    break
                k += 1
            continue
        if ch == "{":
            if not in_function and is_function_header(code[last:k]):
                header = code[last:k]
                lead = len(header) - len(header.lstrip())
                in_function, start_line, start_depth = True, line_of(last + lead), depth
                name = re.search(r"([~\w:<>=!+\-*/\[\]]+)\s*\(", " ".join(header.split()))
                fname = name.group(1) if name else "?"
            depth += 1
            last = k + 1
        elif ch == "}":
            depth -= 1
            last = k + 1
            if in_function and depth == start_depth:
                in_function = False
                length = line_of(k) - start_line + 1
                if length > MAX_LINES:
                    found.append((start_line, fname, length))
        elif ch == ";":
            last = k + 1
    return found


def check_lengths():
    breaches = []
    for f in tracked_sources():
        if not any(f == r or f.startswith(r + "/") for r in LENGTH_ROOTS):
            continue
        for line, name, length in long_functions(f):
            breaches.append(f"{f}:{line}: function {name} is {length} lines (the rule: at most {MAX_LINES})")
    return breaches


def folder_of(include, src_top):
    parts = include.split("/")
    if len(parts) == 1 or parts[0] == "..":
        return None  # a header beside the file
    return parts[0]


def include_breach(f, inc):
    """Why file f (a path from the root) may not include inc, or None."""
    top = f.split("/")[0]
    dst = folder_of(inc, top)
    if dst is None or (dst == top and top != "numeric"):
        return None
    if top in EMBEDDED or dst in EMBEDDED:
        if top not in EMBEDDED and top not in CONSUMERS:
            return "only embedded/ and the consumers (tests, the web page, ...) use the C library"
        if top in EMBEDDED and dst not in EMBEDDED:
            return "the C library includes nothing of the C++ tree"
        return None
    if dst in CONSUMERS:
        return f"{dst}/ is a consumer; nothing includes it"
    if dst not in LIBRARY_ORDER:
        return None  # a system-like path, not the tree's
    if top in LIBRARY_ORDER and LIBRARY_ORDER.index(dst) > LIBRARY_ORDER.index(top):
        return f"{top}/ comes before {dst}/ in the folders' order"
    if top == "numeric" and dst == "numeric":
        src_role = f.split("/")[1] if f.count("/") >= 2 else None
        parts = inc.split("/")
        dst_role = parts[1] if len(parts) >= 3 else None
        for role in (src_role, dst_role):
            if role is not None and role not in NUMERIC_ORDER:
                return (f"numeric/{role}/ has no place in the folders' order (scripts/check_rules.py "
                        "NUMERIC_ORDER, docs/layout.md)")
        if (src_role in NUMERIC_ORDER and dst_role in NUMERIC_ORDER and
                NUMERIC_ORDER.index(dst_role) > NUMERIC_ORDER.index(src_role)):
            return f"numeric/{src_role}/ comes before numeric/{dst_role}/ in the folders' order"
    return None


def check_includes():
    breaches = []
    inc_re = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
    for f in tracked_sources():
        text = open(os.path.join(ROOT, f), encoding="utf-8", errors="replace").read()
        for m in inc_re.finditer(text):
            why = include_breach(f, m.group(1))
            if why:
                line = text.count("\n", 0, m.start()) + 1
                breaches.append(f"{f}:{line}: #include \"{m.group(1)}\": {why}")
    return breaches


# Flags in message text: the libraries under the front ends write "{magnitude}" for words() to render.
# A literal that is one whole option name ("--magnitude": a table's key, Values::text's argument) names no
# flag to a user, and an export's first line names the command that writes that file ("# scalcal export
# --format px4 ..."): the file is the same whichever front end wrote it.
FLAG_ROOTS = ("numeric/", "commands/")
FLAG = re.compile(r"(?<![A-Za-z0-9_-])--[a-z][a-z0-9-]*")
OPTION_KEY = re.compile(r"--[a-z][a-z0-9-]*")
PROVENANCE = re.compile(r"^(# |% |/\* )scalcal ")


def string_literals(text):
    """(line, body) of each string literal outside comments (raw literals included)."""
    i, n = 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif text[i] == "'":
            j = i + 1
            while j < n and text[j] != "'":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        elif text[i] == '"':
            if i > 0 and text[i - 1] == "R" and (i < 2 or not (text[i - 2].isalnum() or text[i - 2] == "_")):
                delim = text[i + 1:text.find("(", i)]
                j = text.find(")" + delim + '"', i)
                j = n if j < 0 else j
                yield text.count("\n", 0, i) + 1, text[i + 2 + len(delim):j]
                i = j + len(delim) + 2
                continue
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            yield text.count("\n", 0, i) + 1, text[i + 1:j]
            i = j + 1
        else:
            i += 1


def flag_breaches_in(text):
    return [(line, body) for line, body in string_literals(text)
            if FLAG.search(body) and not OPTION_KEY.fullmatch(body) and not PROVENANCE.match(body)]


def check_flags():
    breaches = []
    for f in tracked_sources() + [x for x in tracked_files() if x.endswith(".in")]:
        if not f.startswith(FLAG_ROOTS):
            continue
        text = open(os.path.join(ROOT, f), encoding="utf-8", errors="replace").read()
        for line, body in flag_breaches_in(text):
            breaches.append(f"{f}:{line}: a CLI flag in message text ({FLAG.search(body).group(0)}): write "
                            "{name} and words() (numeric/io/option_words.hpp)")
    return breaches


def check_format():
    script = os.path.join(ROOT, "scripts", "check_format.sh")
    r = subprocess.run(["bash", script], cwd=ROOT, capture_output=True, text=True)
    return [] if r.returncode == 0 else [r.stderr.strip() or "check_format.sh failed"]


def main(argv):
    every = ["--lengths", "--includes", "--format", "--flags"]
    chosen = [a for a in argv if a in every] or every
    checks = {"--lengths": check_lengths, "--includes": check_includes, "--format": check_format,
              "--flags": check_flags}
    breaches = []
    for c in chosen:
        breaches += checks[c]()
    for b in breaches:
        print(b, file=sys.stderr)
    print(f"check_rules: {len(breaches)} breaches ({', '.join(c[2:] for c in chosen)})")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

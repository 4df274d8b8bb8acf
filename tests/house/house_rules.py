#!/usr/bin/env python3
"""The house rules that keep Paver's code one-directional and small (issue 39), checked on the
source tree: no engine or compute function over 120 lines and no app function over 150; the
engine's folders include each other in one direction only (the order below); every design key is
spelled in at most two source files outside the tests; README.md at most 200 lines; no name is
defined in two .cpp files of one unity-built target.

Usage: house_rules.py SOURCE_DIR [rule ...]   (rules: functions, folders, keys, readme, unity; default all)
Exit 0 when every rule holds, 1 with one line per breach otherwise."""
import os
import re
import sys

ENGINE_FUNCTION_LINES = 120
APP_FUNCTION_LINES = 150
README_LINES = 200
KEY_FILES = 2
# Lowest first: a folder may include its own and those before it, never one after it.
ENGINE_ORDER = ["core", "mesh", "design", "map", "pattern", "elements", "solver", "io", "report", "cut",
                "pipeline"]


def source_files(root, folders):
    for folder in folders:
        for directory, _, names in os.walk(os.path.join(root, folder)):
            for name in sorted(names):
                if name.endswith((".cpp", ".h")):
                    yield os.path.join(directory, name)


def blank_comments_and_strings(text):
    """The text with comments and string and character literals blanked (newlines kept), so that
    braces and keys inside them do not count."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            delimiter = re.match(r'R"([^(\s]*)\(', text[i:])
            if not delimiter:
                out.append(text[i])
                i += 1
                continue
            end = ")" + delimiter.group(1) + '"'
            j = text.find(end, i)
            j = n if j < 0 else j + len(end)
        elif text[i] in "\"'":
            if text[i] == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator: 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != text[i] and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
        else:
            out.append(text[i])
            i += 1
            continue
        blank = "".join(c if c == "\n" else " " for c in text[i:j])
        if text[i] in "\"'" and j - i >= 2:  # a literal keeps its quotes, so that it can be found
            blank = text[i] + blank[1:-1] + text[j - 1]
        out.append(blank)
        i = j
    return "".join(out)


def matching_brace(text, open_at):
    depth, j = 0, open_at
    while j < len(text):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return j
        j += 1
    return len(text) - 1


def functions(path):
    """(lines, first line, name, head, in_class) of every function body at namespace or class scope."""
    text = blank_comments_and_strings(open(path, encoding="utf-8", errors="replace").read())
    found, i, head_start = [], 0, 0
    scopes = []  # "namespace" or "class", innermost last
    while i < len(text):
        c = text[i]
        if c == "}" and scopes:
            scopes.pop()
        if c in ";}":
            head_start = i + 1
        elif c == ":" and text[head_start:i].strip() in ("public", "private", "protected"):
            head_start = i + 1
        elif c == "{":
            head = text[head_start:i].strip()
            if re.search(r"\bnamespace\b", head) or re.match(r'extern\s*$', head):
                scopes.append("namespace")
                head_start = i + 1  # a namespace's body: its functions are at namespace scope
            elif re.search(r"\b(struct|class|union)\b", head) and "(" not in head.split(":")[0]:
                scopes.append("class")
                head_start = i + 1  # a class's body: its member functions count one by one
            else:
                close = matching_brace(text, i)
                if ")" in head and not head.endswith("=") and not re.search(r"\benum\b", head):
                    first = head_start + (len(text[head_start:i]) - len(text[head_start:i].lstrip()))
                    first_line = text.count("\n", 0, first) + 1
                    last_line = text.count("\n", 0, close) + 1
                    names = re.findall(r"([~\w:]+)\s*\(", head)
                    found.append((last_line - first_line + 1, first_line, names[0] if names else head[:40], head,
                                  bool(scopes) and scopes[-1] == "class"))
                i = close + 1
                head_start = i
                continue
        i += 1
    return found


def check_functions(root):
    problems = []
    for path in source_files(root, ["engine", "compute", "app"]):
        relative = os.path.relpath(path, root)
        limit = APP_FUNCTION_LINES if relative.startswith("app") else ENGINE_FUNCTION_LINES
        for lines, line, name, _, _ in functions(path):
            if lines > limit:
                problems.append(f"{relative}:{line}: {name} has {lines} lines; at most {limit}: split it into "
                                "named steps")
    return problems


def check_folders(root):
    problems = []
    rank = {folder: r for r, folder in enumerate(ENGINE_ORDER)}
    for path in source_files(root, ["engine"]):
        relative = os.path.relpath(path, root)
        folder = relative.split(os.sep)[1]
        if folder not in rank:
            problems.append(f"{relative}: engine/{folder}/ has no place in the folder order; add it to ENGINE_ORDER "
                            "(tests/house/house_rules.py) and docs/ARCHITECTURE.md")
            continue
        for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
            included = re.match(r'\s*#\s*include\s*"(\w+)/', line)
            if not included or included.group(1) not in rank:
                continue
            if rank[included.group(1)] > rank[folder]:
                problems.append(f"{relative}:{number}: engine/{folder}/ includes the later engine/"
                                f"{included.group(1)}/; move the shared part down or the include up")
    return problems


def design_keys(root):
    """The design keys as docs/design_file.md's generated table lists them (first column)."""
    keys = []
    with open(os.path.join(root, "docs", "design_file.md"), encoding="utf-8") as table:
        for line in table:
            key = re.match(r"\| `([a-z_][a-z_.\[\]0-9]*)` \|", line)
            if key:
                keys.append(key.group(1))
    return keys


def string_literals(text):
    """The text of every string literal outside comments."""
    blanked = blank_comments_and_strings(text)
    found, i = [], 0
    while i < len(text):
        if blanked[i] == '"' and text[i] == '"':  # a literal's opening quote survives the blanking
            j = blanked.find('"', i + 1)
            if j < 0:
                break
            found.append(text[i + 1:j])
            i = j + 1
        else:
            i += 1
    return found


def check_keys(root):
    literals = {}
    for path in source_files(root, ["engine", "compute", "app"]):
        text = open(path, encoding="utf-8", errors="replace").read()
        literals[os.path.relpath(path, root)] = "\n".join(string_literals(text))
    problems = []
    for key in design_keys(root):
        if "." not in key:
            continue  # a top-level word (units, edits) is a common word too
        spelled = re.compile(r"(?<![\w.])" + re.escape(key) + r"(?![\w])")
        files = [path for path, text in literals.items() if spelled.search(text)]
        if len(files) > KEY_FILES:
            problems.append(f"design key {key} is spelled in {len(files)} source files ({', '.join(files)}); at most "
                            f"{KEY_FILES}: name it through the design key table (engine/design/design_keys.h)")
    return problems


def check_readme(root):
    lines = sum(1 for _ in open(os.path.join(root, "README.md"), encoding="utf-8"))
    if lines > README_LINES:
        return [f"README.md has {lines} lines; at most {README_LINES}: it is the front page, the reference "
                "belongs in docs/"]
    return []


def parameter_types(head, name):
    """The parameter list of a function head with the parameters' names and defaults dropped:
    "(int a, int b = 0)" -> "(int,int)"."""
    start = head.find("(", head.find(name) + len(name))
    inner = head[start + 1:head.rfind(")")]
    types = []
    for parameter in inner.split(","):
        parameter = parameter.split("=")[0].strip()
        words = re.findall(r"[\w:<>]+|[*&]+", parameter)
        if len(words) > 1 and re.match(r"\w+$", words[-1]):
            words = words[:-1]
        types.append(" ".join(words))
    return "(" + ",".join(types) + ")"


def file_local_definitions(path):
    """The free functions (with their parameter types), constants and types a .cpp defines at
    namespace scope: the names a unity build puts side by side with other files'."""
    text = blank_comments_and_strings(open(path, encoding="utf-8", errors="replace").read())
    names = {}
    for _, line, name, head, in_class in functions(path):
        if in_class or "::" in name or name in ("main", "operator") or "operator" in head:
            continue
        names.setdefault(name + parameter_types(head, name), line)
    for match in re.finditer(r"^(?:static\s+)?(?:inline\s+)?constexpr\s+[\w:<>, ]+?\s+(\w+)\s*(?:\[|=|\{)", text,
                             re.MULTILINE):
        names.setdefault(match.group(1), text.count("\n", 0, match.start()) + 1)
    for match in re.finditer(r"^(?:struct|class|enum class|enum)\s+(\w+)\b(?!;)", text, re.MULTILINE):
        if not text[match.end():].lstrip().startswith(";"):  # a definition, not a declaration
            names.setdefault(match.group(1), text.count("\n", 0, match.start()) + 1)
    return names


def check_unity(root):
    """A name defined in two .cpp files of one unity-built target (the engine, the CLI): the
    sanitizer stage compiles them together and fails with a redefinition, depending on how its
    batches fall (it broke three times when a file was added)."""
    problems = []
    targets = {"engine": [p for p in source_files(root, ["engine"]) if "/cut/" not in p],
               "the CLI": list(source_files(root, [os.path.join("app", "cli")]))}
    for target, paths in targets.items():
        seen = {}
        for path in paths:
            if not path.endswith(".cpp"):
                continue
            relative = os.path.relpath(path, root)
            for name, line in file_local_definitions(path).items():
                if name in seen:
                    problems.append(f"{relative}:{line}: {name} is also defined in {seen[name]}; the unity build of "
                                    f"{target} puts the two files side by side: share one, or rename one")
                else:
                    seen[name] = f"{relative}:{line}"
    return problems


RULES = {"functions": check_functions, "folders": check_folders, "keys": check_keys, "readme": check_readme,
         "unity": check_unity}


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    chosen = sys.argv[2:] or list(RULES)
    problems = []
    for rule in chosen:
        if rule not in RULES:
            print(f"house_rules: no rule '{rule}'; rules: {', '.join(RULES)}", file=sys.stderr)
            return 2
        problems += RULES[rule](root)
    for problem in problems:
        print(problem)
    print(f"house rules ({', '.join(chosen)}): {len(problems)} breaches")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

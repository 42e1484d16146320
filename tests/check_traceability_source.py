#!/usr/bin/env python3
"""Traceability from the dissertation's text, not from the table (issue 20, item 1).

Fails (exit 1, one line per problem) unless spec/traceability.md has a valid row for every
numbered Definition, Lemma, Algorithm, Technique, Listing and Equation that the dissertation
states.

Usage
  check_traceability_source.py ROOT [DISSERTATION] [--require-dissertation]
      check ROOT/spec/traceability.md against ROOT/spec/dissertation-items.txt and, when the
      dissertation text is found, first re-extract the items from it and require the committed
      list to be exactly that extraction
  check_traceability_source.py --extract DISSERTATION
      print the item list (this is how spec/dissertation-items.txt is made:
      `python3 tests/check_traceability_source.py --extract ../shared/seed/<file>.txt
       > spec/dissertation-items.txt`)

Where the dissertation comes from (the decision)
  The dissertation (../shared/seed/dissertation-symmetry-similarity-aware-volumetric-meshing.txt
  relative to the repository root on the development machine) is not part of the repository. A
  fresh clone (e.g. /tmp/fresh, whose ../shared does not exist) and `.ci/run` (`make test` in
  the clone) may not have it. So the item list is committed as spec/dissertation-items.txt, made
  by `--extract`, and the table is always checked against that list; the test never skips and a
  missing list is a failure. When the dissertation is found (the path given, default
  ROOT/../shared/seed/<file>) the script re-extracts and fails on any difference with the
  committed list (a stale or hand-edited list). When it is not found the script says so on one
  line and checks the list for self-consistency instead: the counts in its header match its
  entries and every numbering sequence (kind and chapter) runs 1..max without a hole, so an item
  deleted from the middle of a chapter is still noticed; only the re-extraction is missing.
  `--require-dissertation` (ctest: configure with -DSYMMESH_REQUIRE_DISSERTATION=ON) makes a
  missing dissertation a failure.

Extraction rule (read off how items appear in the .txt, which is a PDF-to-markdown conversion)
  1. Definitions and Lemmas: where the item is stated, "Definition N.M" / "Lemma N.M" (N a
     chapter number or an appendix letter) is followed, after an optional closing "**" and
     blanks, by "(" and its name, and it stands either at the start of a line (after blanks and
     markdown "#", "*", ">") or anywhere wrapped in bold ("**Definition A.7** (Cells, facets)",
     which the conversion ran into the previous paragraph). A parenthesis holding only a roman
     numeral ("Lemma 4.1 (iii)") is a reference to a part, not a name. References in running
     text ("by Lemma 4.2", "(cf. Definition A.7)", "Lemma 6.1 can also be formulated") are not
     at a line start, or not bold, or have no name in parentheses.
  2. Algorithms, Techniques and Listings: the caption, "Algorithm N.M:" with a colon, at the
     start of a line (after blanks and "#", "*"). References ("Algorithm 4.1 generates",
     "Technique 5.8 recursively inserts") have no colon.
  3. Equations: the number label of a display, "(N.M)" with N a chapter number or an appendix
     letter, standing alone on its line (possibly as "$$(N.M)$$"), or at the end of a display
     line (after blanks, "$", "&" or "\\quad", followed by blanks, "$", "\\\\" or the line end),
     or written "\\tag{N.M}". Running text refers to equations as "Equation 6.6", never as a
     bare "(6.6)", and the only other parenthesised numbers ("Lemma 4.1 (iii)") are not N.M.
  4. Numbering holes: each kind numbers consecutively from 1 in every chapter (Algorithms and
     Techniques share one counter: Technique 5.8 follows Algorithm 5.7). A number missing
     between 1 and the largest one found is an item whose caption or label the conversion lost;
     it is listed with "gap" instead of a line number, as the kind the text refers to it by
     ("Algorithm 5.1" is referred to, never captioned; the label "(A.27)", the facets of a
     wedge, is lost; such a hole with no reference takes the kind of its counter).
  Equations are all numbered displays: the dissertation names no equation otherwise.

Rows of spec/traceability.md
  Every markdown table row (a line starting with "|", not a header or its |---| line) whose
  first cell names items counts. Names: a kind word — Def, Defs, Definition(s), Lemma(s),
  Alg, Algs, Algorithm(s), Technique(s), Listing(s), Eq, Eqs, Eq., Equation(s) — followed by one
  or more numbers "N.M" or ranges "N.M–N.K" (en dash or hyphen, same chapter); a number without
  a kind word takes the last kind word before it ("Def A.17 k-simplex, A.9 faces" names Def A.17
  and Def A.9). Other words that introduce numbers (Sec, Secs, Section, Fig, Figure, Table,
  Chapter, Ch) switch the kind off, and so does ";". Every name in the first cell counts, one
  in parentheses too, so a first cell names only the items its row is about.
  A row is valid when
    (a) its second cell (the implementing symbol) and its third cell (the test or property
        that checks it) are both non-empty — not blank, "-" or "—" — and the third names a test
        in backticks or as Suite.Name / Suite.*, or
    (b) a cell after the first starts with a reason: "not computable", "out of scope",
        "not implemented" or "not tested" (the last two must name the open issue, "issue N").
  An item is covered when at least one valid row names it. Also checked, in every table row:
    - every backticked token that looks like a path (contains "/" and ends in ".ext") exists,
      relative to ROOT or, for the symbol cells' short forms like `gen/symmetry_cut.h`,
      relative to ROOT/src/symmesh;
    - every gtest reference Suite.Name (or Suite.*) in a test cell names a TEST of
      tests/unit/*.cpp.
"""

import hashlib
import os
import re
import sys

DISSERTATION_NAME = "dissertation-symmetry-similarity-aware-volumetric-meshing.txt"
ITEMS_FILE = os.path.join("spec", "dissertation-items.txt")
TABLE_FILE = os.path.join("spec", "traceability.md")
KINDS = ["Definition", "Lemma", "Algorithm", "Technique", "Listing", "Equation"]
COUNTER = {"Definition": "Definition", "Lemma": "Lemma", "Algorithm": "Algorithm",
           "Technique": "Algorithm", "Listing": "Listing", "Equation": "Equation"}

NUM = r"(\d+|[A-Z])\.(\d+)"
STATEMENT_AT_START = re.compile(r"^[\s#*>]*(?:\*\*)?(Definition|Lemma) " + NUM +
                                r"(?:\*\*)?\s*\((?![ivx]+\))")
STATEMENT_BOLD = re.compile(r"\*\*(Definition|Lemma) " + NUM + r"\*\*\s*\((?![ivx]+\))")
CAPTION = re.compile(r"^[\s#*]*(Algorithm|Technique|Listing) " + NUM + r"(?:\*\*)?:")
EQ_LABEL = re.compile(r"(?:^|[\s$&]|\\quad)\(" + NUM + r"\)(?=\s|\$|\\\\|$)")
EQ_TAG = re.compile(r"\\tag\{\s*" + NUM + r"\s*\}")
REFERENCE = re.compile(r"\b(Algorithm|Technique|Listing|Definition|Lemma) " + NUM + r"(?![.\d])")


def chapter_key(chapter):
    return (1, chapter) if chapter.isalpha() else (0, int(chapter))


def item_key(item):
    kind, chapter, number = item
    return (KINDS.index(kind), chapter_key(chapter), number)


def item_name(item):
    return "%s %s.%d" % item


def extract(text):
    """Returns {item: line number or None for a numbering hole}."""
    found = {}
    references = {}
    for lineno, line in enumerate(text.split("\n"), 1):
        hits = []
        for rx in (STATEMENT_AT_START, STATEMENT_BOLD, CAPTION):
            for m in rx.finditer(line):
                hits.append((m.group(1), m.group(2), int(m.group(3))))
        for rx in (EQ_LABEL, EQ_TAG):
            for m in rx.finditer(line):
                hits.append(("Equation", m.group(1), int(m.group(2))))
        for item in hits:
            found.setdefault(item, lineno)
        for m in REFERENCE.finditer(line):
            references.setdefault((m.group(2), int(m.group(3))), set()).add(m.group(1))
    # numbering holes, per counter and chapter
    largest = {}
    for kind, chapter, number in found:
        key = (COUNTER[kind], chapter)
        largest[key] = max(largest.get(key, 0), number)
    taken = {(COUNTER[k], c, n) for k, c, n in found}
    for (counter, chapter), top in largest.items():
        for number in range(1, top + 1):
            if (counter, chapter, number) in taken:
                continue
            named = sorted(k for k in references.get((chapter, number), ())
                           if COUNTER.get(k) == counter)
            kind = named[0] if named else counter
            found[(kind, chapter, number)] = None
    return found


def format_items(found, source_text):
    digest = hashlib.sha256(source_text.encode("utf-8")).hexdigest()
    counts = {k: 0 for k in KINDS}
    for kind, _, _ in found:
        counts[kind] += 1
    lines = [
        "# Numbered items of the dissertation, generated by",
        "#   python3 tests/check_traceability_source.py --extract ../shared/seed/" + DISSERTATION_NAME,
        "# Do not edit: tests/check_traceability_source.py compares this list with a re-extraction",
        "# when the dissertation is available, and spec/traceability.md must have a row for each",
        "# item. Second column: the line of the statement/caption/label, or \"gap\" where the text",
        "# conversion lost it (the number is missing between found ones; see the script).",
        "# source-sha256: " + digest,
        "# counts: " + ", ".join("%s %d" % (k, counts[k]) for k in KINDS),
    ]
    for item in sorted(found, key=item_key):
        where = found[item]
        lines.append("%s\t%s" % (item_name(item), "gap" if where is None else "line %d" % where))
    return "\n".join(lines) + "\n"


ITEM_LINE = re.compile(r"^(" + "|".join(KINDS) + r") " + NUM + r"\t(line \d+|gap)$")


def read_items_file(path, problems):
    items = set()
    counts_line = None
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if line.startswith("# counts: "):
                counts_line = line
            if not line or line.startswith("#"):
                continue
            m = ITEM_LINE.match(line)
            if not m:
                problems.append("%s:%d: not an item line: %s" % (ITEMS_FILE, n, line))
                continue
            items.add((m.group(1), m.group(2), int(m.group(3))))
    # self-consistency: the header counts and no holes in any numbering sequence
    counts = {k: 0 for k in KINDS}
    for kind, _, _ in items:
        counts[kind] += 1
    expected = "# counts: " + ", ".join("%s %d" % (k, counts[k]) for k in KINDS)
    if counts_line != expected:
        problems.append("%s: header says '%s' but the entries give '%s'"
                        % (ITEMS_FILE, counts_line, expected))
    largest = {}
    for kind, chapter, number in items:
        key = (COUNTER[kind], chapter)
        largest[key] = max(largest.get(key, 0), number)
    taken = {(COUNTER[k], c, n) for k, c, n in items}
    for (counter, chapter), top in sorted(largest.items()):
        for number in range(1, top + 1):
            if (counter, chapter, number) not in taken:
                problems.append("%s: numbering hole: no %s %s.%d (the list was edited?)"
                                % (ITEMS_FILE, counter, chapter, number))
    return items


# ---- the table ---------------------------------------------------------------------------

KIND_WORDS = {
    "def": "Definition", "defs": "Definition", "definition": "Definition",
    "definitions": "Definition", "lemma": "Lemma", "lemmas": "Lemma", "alg": "Algorithm",
    "algs": "Algorithm", "algorithm": "Algorithm", "algorithms": "Algorithm",
    "technique": "Technique", "techniques": "Technique", "listing": "Listing",
    "listings": "Listing", "eq": "Equation", "eqs": "Equation", "equation": "Equation",
    "equations": "Equation",
}
OFF_WORDS = {"sec", "secs", "section", "sections", "fig", "figs", "figure", "figures", "table",
             "tables", "chapter", "chapters", "ch"}
TOKEN = re.compile(r"(?<![A-Za-z0-9.])" + NUM + r"(?:\s*[–-]\s*" + NUM + r")?|[A-Za-z]+\.?|;")
REASONS = ("not computable", "out of scope", "not implemented", "not tested")
EMPTY = {"", "-", "—", "–"}
BACKTICKED = re.compile(r"`([^`]+)`")
PATHLIKE = re.compile(r"^[\w./-]*/[\w.-]*\.[A-Za-z][A-Za-z0-9]*$")
GTEST_REF = re.compile(r"(?<![\w.])([A-Z][A-Za-z0-9]+)\.(\*|[A-Z][A-Za-z0-9_]*)")


def named_items(cell):
    items = []
    kind = None
    for m in TOKEN.finditer(cell):
        tok = m.group(0)
        if tok == ";":
            kind = None
        elif m.group(1) is None:
            word = tok.rstrip(".").lower()
            if word in KIND_WORDS:
                kind = KIND_WORDS[word]
            elif word in OFF_WORDS:
                kind = None
        elif kind is not None:
            chapter, first = m.group(1), int(m.group(2))
            last = first
            if m.group(3) is not None:
                if m.group(3) != chapter:
                    continue  # a range across chapters is not a range of items
                last = int(m.group(4))
            for number in range(first, last + 1):
                items.append((kind, chapter, number))
    return items


def split_row(line):
    """The cells of a markdown table row; "\\|" inside a cell is a literal bar."""
    line = line.strip()
    if line.startswith("|"):
        line = line[1:]
    if line.endswith("|") and not line.endswith("\\|"):
        line = line[:-1]
    return [c.strip() for c in re.split(r"(?<!\\)\|", line)]


def gtest_names(root):
    names = set()
    unit = os.path.join(root, "tests", "unit")
    rx = re.compile(r"^\s*(?:TEST|TEST_F|TEST_P)\(\s*(\w+)\s*,\s*(\w+)\s*\)", re.M)
    if os.path.isdir(unit):
        for fn in sorted(os.listdir(unit)):
            if fn.endswith(".cpp"):
                with open(os.path.join(unit, fn), encoding="utf-8", errors="replace") as f:
                    names.update(rx.findall(f.read()))
    return names


def check_table(root, items, problems):
    path = os.path.join(root, TABLE_FILE)
    if not os.path.isfile(path):
        problems.append("missing " + TABLE_FILE)
        return
    tests = gtest_names(root)
    suites = {s for s, _ in tests}
    covered = set()
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    header = None
    for n, line in enumerate(lines, 1):
        if not line.lstrip().startswith("|"):
            header = None
            continue
        cells = split_row(line)
        if header is None:
            header = [c.lower() for c in cells]
            continue
        if all(re.fullmatch(r":?-+:?", c) for c in cells if c):
            continue
        where = "%s:%d" % (TABLE_FILE, n)
        # paths in backticks exist
        for cell in cells:
            for tok in BACKTICKED.findall(cell):
                tok = tok.strip()
                if PATHLIKE.match(tok) and not (
                        os.path.exists(os.path.join(root, tok)) or
                        os.path.exists(os.path.join(root, "src", "symmesh", tok))):
                    problems.append("%s: `%s` does not exist" % (where, tok))
        named = named_items(cells[0])
        reason = next((c for c in cells[1:] if c.lower().startswith(REASONS)), None)
        if reason is not None:
            if reason.lower().startswith(("not implemented", "not tested")) and not re.search(
                    r"\bissues? \d+", reason):
                problems.append("%s: '%s' must name the open issue (issue N)"
                                % (where, reason.split(":")[0]))
                continue
        else:
            symbol = cells[1] if len(cells) > 1 else ""
            test = cells[2] if len(cells) > 2 else ""
            if symbol in EMPTY or test in EMPTY:
                if named:
                    problems.append("%s: %s: no symbol and test, and no reason (%s)"
                                    % (where, ", ".join(map(item_name, named)),
                                       " / ".join(REASONS)))
                continue
            refs = GTEST_REF.findall(test)
            if "`" not in test and not refs:
                problems.append("%s: the test cell names no test (backticks or Suite.Name)" % where)
                continue
            bad = [s + "." + t for s, t in refs
                   if s not in suites or (t != "*" and (s, t) not in tests)]
            for b in bad:
                problems.append("%s: no TEST %s in tests/unit/*.cpp" % (where, b))
            if bad:
                continue
        covered.update(named)
    for item in sorted(items - covered, key=item_key):
        problems.append("missing row: " + item_name(item))


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    flags = {a for a in argv[1:] if a.startswith("--")}
    unknown = flags - {"--extract", "--require-dissertation"}
    if unknown or not args or len(args) > 2 or ("--extract" in flags and len(args) != 1):
        sys.stderr.write(__doc__[__doc__.index("Usage"):__doc__.index("Where the dissertation")])
        return 2
    if "--extract" in flags:
        with open(args[0], encoding="utf-8") as f:
            text = f.read()
        sys.stdout.write(format_items(extract(text), text))
        return 0

    root = args[0]
    dissertation = args[1] if len(args) > 1 else os.path.join(
        root, os.pardir, "shared", "seed", DISSERTATION_NAME)
    problems = []
    items_path = os.path.join(root, ITEMS_FILE)
    if not os.path.isfile(items_path):
        print("missing %s (make it with --extract from the dissertation)" % ITEMS_FILE)
        return 1
    if os.path.isfile(dissertation):
        with open(dissertation, encoding="utf-8") as f:
            text = f.read()
        fresh = format_items(extract(text), text)
        with open(items_path, encoding="utf-8") as f:
            committed = f.read()
        if fresh != committed:
            print("%s differs from the extraction of %s; regenerate it with --extract"
                  % (ITEMS_FILE, dissertation))
            old, new = set(committed.split("\n")), set(fresh.split("\n"))
            for line in sorted(old - new):
                print("  only in the committed list: " + line)
            for line in sorted(new - old):
                print("  only in the extraction:     " + line)
            return 1
        print("traceability_source: %s re-extracted from %s" % (ITEMS_FILE, dissertation))
    elif "--require-dissertation" in flags:
        print("dissertation not found at %s (--require-dissertation)" % dissertation)
        return 1
    else:
        print("traceability_source: note: dissertation not found at %s; checking against the "
              "committed %s only" % (dissertation, ITEMS_FILE))
    items = read_items_file(items_path, problems)
    check_table(root, items, problems)
    if problems:
        for p in problems:
            print(p)
        return 1
    counts = {k: sum(1 for i in items if i[0] == k) for k in KINDS}
    print("traceability_source: every item of the dissertation has a valid row (%s)"
          % ", ".join("%d %s" % (counts[k], k) for k in KINDS))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

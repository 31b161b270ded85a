#!/usr/bin/env python3
"""Replaces the text between '<!-- BEGIN name -->' and '<!-- END name -->' in a
Markdown file with standard input (the section is appended if missing), so that
several scripts can each own one generated section of a document. With
--check, changes nothing and fails (showing the difference) when the file's
section is not standard input: for tests that keep a generated section current."""
import difflib
import sys

def main():
    args = sys.argv[1:]
    check = args[:1] == ["--check"]
    if check:
        args = args[1:]
    if len(args) != 2:
        sys.exit("usage: update_doc_section.py [--check] FILE NAME < section.md")
    path, name = args
    begin, end = f"<!-- BEGIN {name} -->", f"<!-- END {name} -->"
    body = sys.stdin.read().rstrip("\n")
    if not body.strip():
        # A producer that failed before printing anything must not blank
        # the section it owns.
        sys.exit(f"update_doc_section.py: nothing on standard input for {name}; {path} left as it was")
    try:
        text = open(path).read()
    except FileNotFoundError:
        text = ""
    block = f"{begin}\n{body}\n{end}"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        new = head + block + tail
    else:
        new = text.rstrip("\n") + ("\n\n" if text else "") + block + "\n"
    if check:
        if new != text:
            sys.stdout.writelines(difflib.unified_diff(text.splitlines(True), new.splitlines(True), path, "generated"))
            sys.exit(f"{path}: section '{name}' is stale; regenerate it")
        return
    open(path, "w").write(new)

main()

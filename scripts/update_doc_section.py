#!/usr/bin/env python3
"""Replaces the text between '<!-- BEGIN name -->' and '<!-- END name -->' in a
Markdown file with standard input (the section is appended if missing), so that
several scripts can each own one generated section of a document."""
import sys

def main():
    if len(sys.argv) != 3:
        sys.exit("usage: update_doc_section.py FILE NAME < section.md")
    path, name = sys.argv[1], sys.argv[2]
    begin, end = f"<!-- BEGIN {name} -->", f"<!-- END {name} -->"
    body = sys.stdin.read().rstrip("\n")
    try:
        text = open(path).read()
    except FileNotFoundError:
        text = ""
    block = f"{begin}\n{body}\n{end}"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        _, tail = rest.split(end, 1)
        text = head + block + tail
    else:
        text = text.rstrip("\n") + ("\n\n" if text else "") + block + "\n"
    open(path, "w").write(text)

main()

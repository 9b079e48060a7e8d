#!/usr/bin/python3
"""Checks the relative links and images of the project's Markdown files.

    /usr/bin/python3 tests/docs/check-links.py [--root DIR] [FILE.md ...]

Without files it checks README.md, CHANGELOG.md and docs/**/*.md under the root (default: the
repository this script is in). Every relative link and image (inline, reference definitions and
HTML src/href) must point at an existing file or folder, and an #anchor into a Markdown file (or
into the same file) must name one of its headings, as GitHub makes their anchors. Links inside
code blocks and code spans, and absolute URLs, are not checked. Prints file:line and the broken
link for each failure and exits 1; exits 0 when every link holds. Standard library only.
"""

import argparse
import glob
import os
import re
import sys
import unicodedata
import urllib.parse

SCRIPT_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
ATX = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$")
SETEXT = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
# [text](target "title") and ![alt](target), the text holding at most one level of brackets.
INLINE = re.compile(r"!?\[(?:[^\[\]\\]|\\.|\[(?:[^\[\]\\]|\\.)*\])*\]\(\s*(<[^>]*>|[^\s()]*(?:\([^\s()]*\)[^\s()]*)*)"
                    r"(?:\s+(?:\"[^\"]*\"|'[^']*'|\([^)]*\)))?\s*\)")
DEFINITION = re.compile(r"^ {0,3}\[((?:[^\]\\]|\\.)+)\]:\s*(<[^>]*>|\S+)")
HTML = re.compile(r"<(?:img|a|source)\b[^>]*?\b(?:src|href)\s*=\s*(\"[^\"]*\"|'[^']*')", re.IGNORECASE)
HTML_ANCHOR = re.compile(r"<[a-z][^>]*?\b(?:id|name)\s*=\s*(\"[^\"]*\"|'[^']*')", re.IGNORECASE)
CODE_SPAN = re.compile(r"(`+)(.+?)(?<!`)\1(?!`)")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


def strip_code_spans(line):
    """The line with its code spans blanked, so that their text holds no links."""
    return CODE_SPAN.sub(lambda match: " " * len(match.group(0)), line)


def lines_outside_code(text):
    """(line number, line) of the lines outside fenced and indented code blocks."""
    fence = None
    previous_blank = True
    for number, line in enumerate(text.splitlines(), 1):
        match = FENCE.match(line)
        if fence:
            if match and match.group(1)[0] == fence[0] and len(match.group(1)) >= len(fence) and \
                    not line.strip()[len(match.group(1)):].strip():
                fence = None
            previous_blank = False
            continue
        if match:
            fence = match.group(1)
            continue
        if previous_blank and (line.startswith("    ") or line.startswith("\t")) and line.strip():
            continue  # an indented code block (a list item's continuation is indented too: rare here)
        previous_blank = not line.strip()
        yield number, line


def heading_text(markdown):
    """The text GitHub renders for a heading's Markdown."""
    text = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", markdown)     # images: their alt text
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)          # links: their text
    text = re.sub(r"\[([^\]]*)\]\[[^\]]*\]", r"\1", text)         # reference links
    text = re.sub(r"<[^>]+>", "", text)                           # HTML tags
    text = CODE_SPAN.sub(lambda match: match.group(2).strip(), text)
    text = re.sub(r"(\*\*|__)(.+?)\1", r"\2", text)
    text = re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"\1", text)
    text = re.sub(r"(?<![\w_])_(?!\s)(.+?)(?<!\s)_(?![\w_])", r"\1", text)
    text = re.sub(r"~~(.+?)~~", r"\1", text)
    text = re.sub(r"\\(.)", r"\1", text)
    return text.strip()


def slug(text):
    """GitHub's anchor of a heading's text (github-slugger): lower case, punctuation dropped,
    spaces as hyphens."""
    kept = []
    for char in text.lower():
        category = unicodedata.category(char)
        if char in " -_" or category[0] in "LNM":
            kept.append("-" if char == " " else char)
    return "".join(kept)


class Document:
    """A Markdown file's anchors."""

    def __init__(self, path):
        with open(path, encoding="utf-8") as stream:
            self.text = stream.read()
        self.anchors = set()
        counts = {}
        previous = None
        for _, line in lines_outside_code(self.text):
            heading = None
            match = ATX.match(line)
            if match:
                heading = match.group(2) or ""
            elif previous is not None and previous.strip() and SETEXT.match(line) and \
                    not ATX.match(previous) and not previous.lstrip().startswith(("-", "*", ">", "|")):
                heading = previous.strip()
            if heading is not None:
                base = slug(heading_text(heading))
                anchor = base if base not in counts else f"{base}-{counts[base]}"
                counts[base] = counts.get(base, 0) + 1
                self.anchors.add(anchor)
            for match in HTML_ANCHOR.finditer(line):
                self.anchors.add(match.group(1)[1:-1])
            previous = line


class Checker:
    def __init__(self, root):
        self.root = os.path.abspath(root)
        self.documents = {}
        self.failures = []

    def document(self, path):
        path = os.path.abspath(path)
        if path not in self.documents:
            self.documents[path] = Document(path)
        return self.documents[path]

    def fail(self, path, number, target, reason):
        self.failures.append(f"{os.path.relpath(path, self.root)}:{number}: broken link '{target}': {reason}")

    def check_target(self, path, number, target):
        target = target.strip()
        if target.startswith("<") and target.endswith(">"):
            target = target[1:-1].strip()
        if not target or SCHEME.match(target) or target.startswith("//"):
            return
        location, _, anchor = target.partition("#")
        location = urllib.parse.unquote(location.partition("?")[0])
        anchor = urllib.parse.unquote(anchor)
        if location:
            base = self.root if location.startswith("/") else os.path.dirname(path)
            resolved = os.path.normpath(os.path.join(base, location.lstrip("/")))
            if not os.path.exists(resolved):
                self.fail(path, number, target, f"no file {os.path.relpath(resolved, self.root)}")
                return
            if os.path.relpath(resolved, self.root).startswith(".."):
                self.fail(path, number, target, "points outside the repository")
                return
        else:
            resolved = path
        if not anchor:
            return
        if os.path.isdir(resolved) or not resolved.lower().endswith((".md", ".markdown")):
            if re.fullmatch(r"L\d+(-L\d+)?", anchor) or os.path.isdir(resolved):
                return  # line anchors of a source file; a folder's README is not checked
            self.fail(path, number, target, "an anchor into a file that is not Markdown")
            return
        if anchor not in self.document(resolved).anchors:
            self.fail(path, number, target,
                      f"no heading '#{anchor}' in {os.path.relpath(resolved, self.root)}")

    def check_file(self, path):
        document = self.document(path)
        for number, line in lines_outside_code(document.text):
            plain = strip_code_spans(line)
            for match in INLINE.finditer(plain):
                self.check_target(path, number, match.group(1))
            match = DEFINITION.match(plain)
            if match:
                self.check_target(path, number, match.group(2))
            for match in HTML.finditer(plain):
                self.check_target(path, number, match.group(1)[1:-1])


def default_files(root):
    files = [os.path.join(root, name) for name in ("README.md", "CHANGELOG.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=SCRIPT_ROOT, help="the repository (default: this script's)")
    parser.add_argument("files", nargs="*", help="Markdown files (default: README.md, CHANGELOG.md, docs/**/*.md)")
    arguments = parser.parse_args()
    checker = Checker(arguments.root)
    files = [os.path.abspath(name) for name in arguments.files] or default_files(checker.root)
    checked = 0
    for path in files:
        if not os.path.exists(path):
            checker.failures.append(f"{os.path.relpath(path, checker.root)}: missing")
            continue
        checker.check_file(path)
        checked += 1
    for failure in checker.failures:
        print(failure)
    if checker.failures:
        print(f"check-links.py: {len(checker.failures)} broken link(s) in {checked} file(s)", file=sys.stderr)
        return 1
    print(f"check-links.py: every link holds in {checked} file(s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

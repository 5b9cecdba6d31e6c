#!/usr/bin/env python3
"""Every relative link and image of README.md, CHANGELOG.md and docs/*.md resolves to a file.

Usage: scripts/check_doc_links.py [REPO]   (default: the repository this script is in)
Prints one line per broken link, FILE:LINE: TARGET, and exits 1 when there is any.
Links with a scheme (https:, mailto:) and in-page anchors (#...) are not checked.
"""
import glob
import os
import re
import sys

# [text](target) and ![alt](target), the target up to a space or ')'; <img src="target">
MARKDOWN_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HTML_SRC = re.compile(r"<img[^>]*\ssrc=\"([^\"]+)\"")


def broken_links(path):
    base = os.path.dirname(path)
    in_code = False
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        if line.lstrip().startswith("```"):
            in_code = not in_code
            continue
        if in_code:
            continue
        line = re.sub(r"`[^`]*`", "", line)  # inline code is not a link
        for target in MARKDOWN_LINK.findall(line) + HTML_SRC.findall(line):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            file = target.split("#", 1)[0]
            if not os.path.exists(os.path.join(base, file)):
                yield number, target


def main():
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(
        os.path.dirname(os.path.abspath(__file__)))
    pages = [os.path.join(repo, "README.md"), os.path.join(repo, "CHANGELOG.md")]
    pages += sorted(glob.glob(os.path.join(repo, "docs", "*.md")))
    broken = 0
    for page in pages:
        if not os.path.exists(page):
            continue
        for number, target in broken_links(page):
            print(f"{os.path.relpath(page, repo)}:{number}: {target}")
            broken += 1
    print(f"{len(pages)} pages, {broken} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())

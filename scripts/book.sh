#!/usr/bin/env bash
# The book (docs/, mdBook): build it into target/book with warnings as errors, then check that
# every relative link and image of the built pages exists, anchors included.
#
#   bash scripts/book.sh
#
# mdBook (pinned) is installed into .tools/ on first use (a debug build: it compiles in half
# the time of a release one and builds this book in two seconds). The commands the book and the README
# show, and the outputs they print, are checked by `cargo test -p impax-cli --test
# cli book_commands` (part of `cargo test --workspace`), as are the links of the Markdown sources.
set -euo pipefail
cd "$(dirname "$0")/.."
version=0.5.4
tools="$PWD/.tools"
if ! "$tools/bin/mdbook" --version 2>/dev/null | grep -q "v$version\$"; then
    echo "== installing mdBook $version into .tools/"
    cargo install mdbook --version "$version" --locked --no-default-features --features search \
        --root "$tools" --quiet --debug
fi

echo "== mdbook build docs (warnings are errors)"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
rm -rf target/book
"$tools/bin/mdbook" build docs 2>&1 | tee "$log"
if grep -qE '\b(WARN|ERROR)\b' "$log"; then
    echo "scripts/book.sh: mdBook printed warnings or errors (above)" >&2
    exit 1
fi

echo "== links and images of the built book"
python3 - target/book <<'PY'
import html.parser, os, sys, urllib.parse

root = sys.argv[1]

class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.refs = set(), []
    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("id", "name") and value:
                self.ids.add(value)
            if name in ("href", "src") and value:
                self.refs.append(value)

pages = {}
for folder, _, files in os.walk(root):
    for f in files:
        # 404.html is for a web server: its links are relative to the site's root.
        if f.endswith(".html") and f != "404.html":
            path = os.path.normpath(os.path.join(folder, f))
            page = Page()
            with open(path, encoding="utf-8") as text:
                page.feed(text.read())
            pages[path] = page

broken = []
for path, page in sorted(pages.items()):
    for ref in page.refs:
        url = urllib.parse.urlsplit(ref)
        if url.scheme or ref.startswith("//"):
            continue  # external: not checked here
        target = path
        if url.path:
            target = os.path.normpath(os.path.join(os.path.dirname(path), urllib.parse.unquote(url.path)))
            if url.path.endswith("/"):
                target = os.path.join(target, "index.html")
        if not os.path.exists(target):
            broken.append(f"{path}: {ref}: no file {target}")
        elif url.fragment and target in pages and urllib.parse.unquote(url.fragment) not in pages[target].ids:
            broken.append(f"{path}: {ref}: no anchor #{url.fragment} in {target}")

for b in broken:
    print(b, file=sys.stderr)
if broken:
    sys.exit(f"scripts/book.sh: {len(broken)} broken links or images")
print(f"{len(pages)} pages, every relative link and image found")
PY
echo "== the book is in target/book/index.html"

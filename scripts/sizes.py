#!/usr/bin/env python3
"""The size rules of the sources: no file over 800 lines and no function over 150 lines (from
its `fn` line to its closing brace) in crates/*/src. Prints every violation; exit 1 if any.

    python3 scripts/sizes.py [REPOSITORY]

Comments, strings and character literals are blanked before braces are matched.
"""
import re, sys, pathlib

def strip(src):
    # Replace comments, strings and char literals with spaces, keeping newlines.
    out = []; i = 0; n = len(src)
    while i < n:
        c = src[i]
        if src.startswith('//', i):
            j = src.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j; continue
        if src.startswith('/*', i):
            depth = 1; j = i + 2
            while j < n and depth:
                if src.startswith('/*', j): depth += 1; j += 2
                elif src.startswith('*/', j): depth -= 1; j += 2
                else: j += 1
            out.append(re.sub(r'[^\n]', ' ', src[i:j])); i = j; continue
        m = re.match(r'b?r(#*)"', src[i:i+10])
        if m and (i == 0 or not (src[i-1].isalnum() or src[i-1] == '_')):
            hashes = m.group(1); end = '"' + hashes
            j = src.find(end, i + len(m.group(0))) + len(end)
            out.append(re.sub(r'[^\n]', ' ', src[i:j])); i = j; continue
        if c == '"':
            j = i + 1
            while src[j] != '"':
                j += 2 if src[j] == '\\' else 1
            j += 1
            out.append(re.sub(r'[^\n]', ' ', src[i:j])); i = j; continue
        if c == "'":
            m = re.match(r"'(\\.[^']*|[^\\'])'", src[i:i+12])
            if m:
                out.append(' ' * len(m.group(0))); i += len(m.group(0)); continue
        out.append(c); i += 1
    return ''.join(out)

def functions(path):
    text = strip(path.read_text())
    res = []
    for m in re.finditer(r'\bfn\s+([A-Za-z_][A-Za-z0-9_]*)', text):
        # find the opening brace of the body (or ';' for declarations)
        j = m.end(); depth = 0
        while j < len(text):
            ch = text[j]
            if ch in '(<[': depth += 1
            elif ch in ')>]': depth -= 1
            elif ch == ';' and depth <= 0: j = -1; break
            elif ch == '{' and depth <= 0: break
            j += 1
        if j < 0 or j >= len(text): continue
        # '->' contains '>' which unbalances; recount ignoring '->'
        k = j; d = 0
        while k < len(text):
            if text[k] == '{': d += 1
            elif text[k] == '}':
                d -= 1
                if d == 0: break
            k += 1
        start = text.count('\n', 0, m.start()) + 1
        end = text.count('\n', 0, k) + 1
        res.append((m.group(1), start, end - start + 1))
    return res

def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.')
    bad = 0
    for p in sorted(root.glob('crates/*/src/**/*.rs')):
        rel = p.relative_to(root)
        lines = p.read_text().count('\n')
        if lines > 800:
            print(f'FILE {rel}: {lines} lines'); bad += 1
        for name, start, length in functions(p):
            if length > 150:
                print(f'FN   {rel}:{start} {name}: {length} lines'); bad += 1
    print(f'{bad} over the limits')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())

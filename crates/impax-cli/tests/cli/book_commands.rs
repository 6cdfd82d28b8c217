//! The book (`docs/src/`) and the README, checked against the binary, so that they cannot drift:
//!
//! * every `impax …` command shown in a ```` ```sh ```` or ```` ```console ```` block runs from the
//!   repository's root and exits 0 (files it would write go to a temporary folder);
//! * in a ```` ```console ```` block, the lines after `$ impax …` are exactly what the command
//!   prints on standard output;
//! * every relative link and image points to a file that exists.
//!
//! The conventions (which lines are commands, what is skipped, `<!-- no-check: REASON -->`)
//! are written down for authors in the book's "Contributing to the book"
//! (`docs/src/contributing.md`).

use assert_cmd::Command;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The repository's root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .expect("the repository's root")
}

/// `README.md` and every Markdown page of the book, in a fixed order.
fn pages() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("a directory entry").path())
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|x| x == "md") {
                out.push(path);
            }
        }
    }
    let root = root();
    let mut out = vec![root.join("README.md")];
    walk(&root.join("docs/src"), &mut out);
    assert!(out.len() > 10, "the book's pages are missing: {out:?}");
    out
}

fn relative(path: &Path) -> String {
    path.strip_prefix(root())
        .unwrap_or(path)
        .display()
        .to_string()
}

/// One command shown in a page, with the output a `console` block shows after it.
#[derive(Debug)]
struct Example {
    /// `file:line` of the command.
    place: String,
    /// The command line, continuation lines joined.
    command: String,
    /// The lines shown after the command in a `console` block (`None` in a `sh` block).
    expected: Option<Vec<String>>,
    /// Why it is not run, if it is not.
    skip: Option<&'static str>,
}

/// Drop a trailing `# comment` (a `#` after whitespace).
fn strip_comment(line: &str) -> &str {
    let bytes = line.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'#' && i > 0 && bytes[i - 1].is_ascii_whitespace() {
            return line[..i].trim_end();
        }
    }
    line.trim_end()
}

/// Why a command is shown but not run, if it is not run.
fn skip_reason(command: &str, no_check: bool) -> Option<&'static str> {
    if no_check {
        return Some("<!-- no-check --> block");
    }
    if command.contains('…') || command.contains("...") {
        return Some("placeholder `…`");
    }
    let placeholder = command
        .split(|c: char| !c.is_ascii_alphabetic())
        .any(|word| word.len() >= 2 && word.chars().all(|c| c.is_ascii_uppercase()));
    if placeholder {
        return Some("placeholder in capitals");
    }
    let words: Vec<&str> = command.split_whitespace().collect();
    if words.get(1) == Some(&"explore") && !words.contains(&"--out") {
        return Some("starts a server");
    }
    None
}

/// The commands of one page.
fn examples(path: &Path) -> Vec<Example> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let lines: Vec<&str> = text.lines().collect();
    let mut out: Vec<Example> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let fence = lines[i].trim_start();
        if !fence.starts_with("```") {
            i += 1;
            continue;
        }
        let lang = fence
            .trim_start_matches('`')
            .split(|c: char| c == ',' || c.is_whitespace())
            .next()
            .unwrap_or("")
            .to_string();
        let no_check = i > 0 && lines[i - 1].trim_start().starts_with("<!-- no-check");
        let start = i + 1;
        let mut end = start;
        while end < lines.len() && lines[end].trim() != "```" {
            end += 1;
        }
        let block = &lines[start..end.min(lines.len())];
        let first_line = start + 1; // 1-based line number of block[0]
        match lang.as_str() {
            "sh" => {
                let mut k = 0;
                while k < block.len() {
                    let at = first_line + k;
                    let mut command = String::new();
                    loop {
                        let line = strip_comment(block[k]);
                        match line.strip_suffix('\\') {
                            Some(head) if k + 1 < block.len() => {
                                command.push_str(head.trim());
                                command.push(' ');
                                k += 1;
                            }
                            _ => {
                                command.push_str(line.trim());
                                k += 1;
                                break;
                            }
                        }
                    }
                    if command.starts_with("impax ") || command == "impax" {
                        out.push(Example {
                            place: format!("{}:{at}", relative(path)),
                            skip: skip_reason(&command, no_check),
                            command,
                            expected: None,
                        });
                    }
                }
            }
            "console" => {
                let mut k = 0;
                while k < block.len() {
                    let Some(rest) = block[k].strip_prefix("$ ") else {
                        k += 1;
                        continue;
                    };
                    let at = first_line + k;
                    let mut command = rest.trim().to_string();
                    while let Some(head) = command.strip_suffix('\\') {
                        k += 1;
                        command = format!("{} {}", head.trim(), block[k].trim());
                    }
                    k += 1;
                    let mut shown = Vec::new();
                    while k < block.len() && !block[k].starts_with("$ ") {
                        shown.push(block[k].to_string());
                        k += 1;
                    }
                    if command.starts_with("impax ") || command == "impax" {
                        out.push(Example {
                            place: format!("{}:{at}", relative(path)),
                            skip: skip_reason(&command, no_check),
                            command,
                            expected: Some(shown),
                        });
                    }
                }
            }
            _ => {}
        }
        i = end + 1;
    }
    out
}

/// Split a command line into words (single and double quotes group; no expansion).
fn words(command: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut in_word = false;
    let mut quote: Option<char> = None;
    for c in command.chars() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => word.push(c),
            None if c == '\'' || c == '"' => {
                quote = Some(c);
                in_word = true;
            }
            None if c.is_whitespace() => {
                if in_word {
                    out.push(std::mem::take(&mut word));
                    in_word = false;
                }
            }
            None => {
                word.push(c);
                in_word = true;
            }
        }
    }
    if in_word {
        out.push(word);
    }
    out
}

/// The flags whose value is a file or folder the command writes.
const OUTPUT_FLAGS: [&str; 4] = ["--out", "--plot", "--csv", "--animate"];

/// Run one example; `Err` says what went wrong.
fn run(example: &Example, scratch: &Path) -> Result<(), String> {
    let mut args = words(&example.command);
    assert_eq!(args.remove(0), "impax");
    // Files the command writes go to the scratch folder; their paths in the output are
    // compared as the page writes them.
    let mut renamed: Vec<(String, String)> = Vec::new();
    let mut redirect = false;
    let mut kept = Vec::new();
    let mut it = args.into_iter();
    while let Some(arg) = it.next() {
        if arg == ">" {
            it.next().ok_or("`>` without a file")?;
            redirect = true;
            continue;
        }
        if let Some(file) = arg.strip_prefix('>') {
            if !file.is_empty() {
                redirect = true;
                continue;
            }
        }
        if OUTPUT_FLAGS.contains(&arg.as_str()) {
            let shown = it.next().ok_or_else(|| format!("{arg} without a value"))?;
            let path = scratch.join(shown.replace('/', "_"));
            let path = path.to_str().expect("a UTF-8 scratch path").to_string();
            renamed.push((path.clone(), shown));
            kept.push(arg);
            kept.push(path);
            continue;
        }
        kept.push(arg);
    }
    let started = Instant::now();
    let output = Command::cargo_bin("impax")
        .map_err(|e| format!("no impax binary: {e}"))?
        .args(&kept)
        .current_dir(root())
        .timeout(Duration::from_secs(300))
        .output()
        .map_err(|e| format!("cannot run impax: {e}"))?;
    let seconds = started.elapsed().as_secs_f64();
    if seconds > 20.0 {
        eprintln!(
            "{}: `{}` took {seconds:.1} s",
            example.place, example.command
        );
    }
    if !output.status.success() {
        return Err(format!(
            "exit code {:?}; stderr: {}",
            output.status.code(),
            String::from_utf8_lossy(&output.stderr).trim_end()
        ));
    }
    let Some(expected) = &example.expected else {
        return Ok(());
    };
    if expected.iter().all(|l| l.trim().is_empty()) || redirect {
        return Ok(());
    }
    let mut actual = String::from_utf8(output.stdout).map_err(|e| format!("stdout: {e}"))?;
    for (path, shown) in &renamed {
        actual = actual.replace(path.as_str(), shown);
    }
    let actual = actual.trim_end_matches('\n');
    let expected = expected.join("\n");
    let expected = expected.trim_end_matches('\n');
    if actual == expected {
        return Ok(());
    }
    let (a, e): (Vec<&str>, Vec<&str>) = (actual.lines().collect(), expected.lines().collect());
    let first = (0..a.len().max(e.len()))
        .find(|&k| a.get(k) != e.get(k))
        .unwrap_or(0);
    Err(format!(
        "the output differs from the page from its line {} on:\n  page:   {:?}\n  prints: {:?}\n\
         the whole output:\n{actual}",
        first + 1,
        e.get(first).copied().unwrap_or("<end>"),
        a.get(first).copied().unwrap_or("<end>"),
    ))
}

/// A scratch folder for the files the commands write, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("impax-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("a scratch folder");
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

#[test]
fn every_command_runs_and_prints_what_the_page_shows() {
    let scratch = Scratch::new("book-commands");
    let all: Vec<Example> = pages().iter().flat_map(|p| examples(p)).collect();
    let run_here: Vec<&Example> = all.iter().filter(|e| e.skip.is_none()).collect();
    let compared = run_here
        .iter()
        .filter(|e| e.expected.as_ref().is_some_and(|x| !x.is_empty()))
        .count();
    assert!(
        run_here.len() >= 50 && compared >= 8,
        "too few commands found ({} run, {compared} with output): is the parser broken?",
        run_here.len()
    );
    // The conventions themselves: each kind of skip is exercised by the pages.
    let skipped: Vec<&Example> = all.iter().filter(|e| e.skip.is_some()).collect();
    for e in &skipped {
        eprintln!(
            "shown, not run ({}): {}: {}",
            e.skip.unwrap(),
            e.place,
            e.command
        );
    }
    let mut failures = Vec::new();
    for example in &run_here {
        if let Err(why) = run(example, &scratch.0) {
            failures.push(format!("{}: `{}`: {why}", example.place, example.command));
        }
    }
    eprintln!(
        "{} commands run ({compared} outputs compared), {} shown only",
        run_here.len(),
        skipped.len()
    );
    assert!(
        failures.is_empty(),
        "{} of {} commands failed:\n\n{}",
        failures.len(),
        run_here.len(),
        failures.join("\n\n")
    );
}

/// Every `[text](target)` and `![alt](target)` outside code, with its line.
fn links(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut in_fence = false;
    for (n, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            in_fence = !in_fence;
            continue;
        }
        if in_fence {
            continue;
        }
        // Drop inline code spans.
        let mut plain = String::new();
        for (k, part) in line.split('`').enumerate() {
            if k % 2 == 0 {
                plain.push_str(part);
            }
        }
        let mut rest = plain.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(close) = after.find(')') else { break };
            out.push((n + 1, after[..close].trim().to_string()));
            rest = &after[close + 1..];
        }
    }
    out
}

#[test]
fn every_relative_link_and_image_exists() {
    let mut broken = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).expect("a page");
        for (line, target) in links(&text) {
            if target.is_empty()
                || target.starts_with('#')
                || target.contains("://")
                || target.starts_with("mailto:")
            {
                continue;
            }
            let file = target.split('#').next().unwrap_or("");
            let resolved = page.parent().expect("a folder").join(file);
            checked += 1;
            if !resolved.exists() {
                broken.push(format!("{}:{line}: {target}", relative(&page)));
            }
        }
    }
    assert!(
        checked > 50,
        "too few links found ({checked}): is the parser broken?"
    );
    assert!(
        broken.is_empty(),
        "links to files that do not exist:\n{}",
        broken.join("\n")
    );
}

#[test]
fn the_parser_reads_the_conventions() {
    let page = "\
```sh
impax compare --law whittaker   # a comment
impax sweep --grid friction=0:1:3 \\
    --law energetic
impax compare SCENARIO.toml
impax explore
cargo run --release --bin impax -- compare
```

<!-- no-check: failing on purpose -->
```sh
impax resolve --w 1,2,1 --v 0.5,-1 --friction 0.4 --restitution 0.7
```

```console
$ impax paper liu2012 --json
{
$ impax explore --out page
```
";
    let scratch = Scratch::new("book-parser");
    let path = scratch.0.join("page.md");
    std::fs::write(&path, page).expect("a page");
    let found = examples(&path);
    let summary: Vec<(&str, Option<&str>, Option<usize>)> = found
        .iter()
        .map(|e| {
            (
                e.command.as_str(),
                e.skip,
                e.expected.as_ref().map(|x| x.len()),
            )
        })
        .collect();
    assert_eq!(
        summary,
        vec![
            ("impax compare --law whittaker", None, None),
            (
                "impax sweep --grid friction=0:1:3 --law energetic",
                None,
                None
            ),
            (
                "impax compare SCENARIO.toml",
                Some("placeholder in capitals"),
                None
            ),
            ("impax explore", Some("starts a server"), None),
            (
                "impax resolve --w 1,2,1 --v 0.5,-1 --friction 0.4 --restitution 0.7",
                Some("<!-- no-check --> block"),
                None
            ),
            ("impax paper liu2012 --json", None, Some(1)),
            ("impax explore --out page", None, Some(0)),
        ]
    );
    assert_eq!(
        words(r#"impax map --out "a b.png" > x.csv"#),
        ["impax", "map", "--out", "a b.png", ">", "x.csv"]
    );
    assert_eq!(
        links("see [a](b.md#c) and ![i](img/x.png), not `[x](y)`"),
        [(1, "b.md#c".to_string()), (1, "img/x.png".to_string())]
    );
}

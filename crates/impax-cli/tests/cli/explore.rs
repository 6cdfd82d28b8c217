//! `impax explore`: the page's files written with `--out` (the bytes of `web/`), the page
//! served on 127.0.0.1 with the right MIME types, and a port in use as bad input.
//!
//! Regressions (issue 17, item 11): a request line of 200 MB was buffered whole (the server's
//! memory grew by 400 MB) — now an overlong line gets `414` and the connection is closed;
//! the body of a `POST` was parsed as the next request (a second response, here `200` for the
//! `GET` inside the body) — now one `405` with `Allow: GET, HEAD`, then the connection closes.
//! The single-write responses and the bounded reads are unit tests of `explore::answer`.

use assert_cmd::cargo::cargo_bin;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::PathBuf;
use std::process::{Child, Stdio};

const FILES: [&str; 9] = [
    "index.html",
    "style.css",
    "impax.js",
    "views.js",
    "explorer.js",
    "multi.js",
    "mechanism.js",
    "conserved.js",
    "impax_wasm.wasm",
];

fn web(name: &str) -> Vec<u8> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../web");
    std::fs::read(dir.join(name)).unwrap()
}

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-explore-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn out_writes_the_page_files() {
    let dir = temp_dir("out");
    let out = crate::support::impax()
        .args(["explore", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("index.html"));
    for name in FILES {
        assert_eq!(std::fs::read(dir.join(name)).unwrap(), web(name), "{name}");
    }
    // Every file of web/ (its folder test/ aside) is one of the page's.
    let web_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../web");
    for entry in std::fs::read_dir(web_dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_file() {
            assert!(FILES.contains(&name.as_str()), "web/{name} is not embedded");
        }
    }
    // The base64 copy for file:// decodes to the module.
    let script = std::fs::read_to_string(dir.join("impax_wasm.js")).unwrap();
    let b64 = script.split('"').nth(1).expect("IMPAX_WASM_BASE64 = \"…\"");
    assert_eq!(decode_base64(b64), web("impax_wasm.wasm"));
    std::fs::remove_dir_all(&dir).unwrap();
}

fn decode_base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let mut out = Vec::new();
    for chunk in text.as_bytes().chunks(4) {
        let n = chunk
            .iter()
            .take_while(|&&c| c != b'=')
            .enumerate()
            .fold(0u32, |n, (k, &c)| n | u32::from(value(c)) << (18 - 6 * k));
        let len = chunk.iter().filter(|&&c| c != b'=').count() - 1;
        out.extend_from_slice(&n.to_be_bytes()[1..1 + len]);
    }
    out
}

#[test]
fn out_to_a_file_is_bad_input() {
    let file = temp_dir("file");
    std::fs::write(&file, b"not a folder").unwrap();
    let out = crate::support::impax()
        .args(["explore", "--out"])
        .arg(file.join("sub"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--out"), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1);
    std::fs::remove_file(&file).unwrap();
}

/// The server, killed when dropped.
struct Server(Child);

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn start() -> (Server, String) {
    let mut child = std::process::Command::new(cargo_bin("impax"))
        .args(["explore", "--port", "0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let addr = line
        .split("http://")
        .nth(1)
        .and_then(|s| s.split('/').next())
        .unwrap_or_else(|| panic!("no URL in {line:?}"))
        .to_string();
    (Server(child), addr)
}

/// `GET path` with `Connection: close`: status line, headers, body.
fn get(addr: &str, path: &str) -> (String, String, Vec<u8>) {
    let mut s = TcpStream::connect(addr).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).unwrap();
    let split = raw.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
    let head = String::from_utf8(raw[..split].to_vec()).unwrap();
    let status = head.lines().next().unwrap().to_string();
    (status, head, raw[split + 4..].to_vec())
}

#[test]
fn serves_the_page_with_mime_types() {
    let (_server, addr) = start();
    let (status, head, body) = get(&addr, "/");
    assert_eq!(status, "HTTP/1.1 200 OK");
    assert!(head.contains("Content-Type: text/html"), "{head}");
    assert_eq!(body, web("index.html"));
    let (status, head, body) = get(&addr, "/impax_wasm.wasm");
    assert_eq!(status, "HTTP/1.1 200 OK");
    assert!(head.contains("Content-Type: application/wasm"), "{head}");
    assert_eq!(body, web("impax_wasm.wasm"));
    let (_, head, _) = get(&addr, "/explorer.js");
    assert!(head.contains("Content-Type: text/javascript"), "{head}");
    let (status, _, _) = get(&addr, "/../Cargo.toml");
    assert_eq!(status, "HTTP/1.1 404 Not Found");
}

#[test]
fn a_port_in_use_is_bad_input() {
    let taken = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = taken.local_addr().unwrap().port().to_string();
    let out = crate::support::impax()
        .args(["explore", "--port", &port])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains(&format!("--port {port}")), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1);
}

/// Everything the server sends on `s` until it closes the connection (or, after a regression,
/// until 20 s of silence, so that a hanging server fails the test instead of blocking it).
fn read_until_closed(s: &mut TcpStream) -> Vec<u8> {
    s.set_read_timeout(Some(std::time::Duration::from_secs(20)))
        .unwrap();
    let mut raw = Vec::new();
    let mut buf = [0u8; 65536];
    loop {
        match s.read(&mut buf) {
            Ok(0) | Err(_) => return raw,
            Ok(n) => raw.extend_from_slice(&buf[..n]),
        }
    }
}

/// The status lines in a stream of responses.
fn status_lines(raw: &[u8]) -> Vec<String> {
    let text = String::from_utf8_lossy(raw);
    text.match_indices("HTTP/1.1 ")
        .map(|(i, _)| text[i..].lines().next().unwrap().to_string())
        .collect()
}

#[test]
fn a_post_with_a_body_gets_one_405_and_the_connection_closes() {
    let (_server, addr) = start();
    let mut s = TcpStream::connect(&addr).unwrap();
    let body = format!("GET /style.css HTTP/1.1\r\nHost: {addr}\r\n\r\n");
    write!(
        s,
        "POST / HTTP/1.1\r\nHost: {addr}\r\nContent-Length: {}\r\n\r\n{body}",
        body.len()
    )
    .unwrap();
    let raw = read_until_closed(&mut s);
    assert_eq!(status_lines(&raw), ["HTTP/1.1 405 Method Not Allowed"]);
    let text = String::from_utf8_lossy(&raw);
    assert!(text.contains("\r\nAllow: GET, HEAD\r\n"), "{text}");
    assert!(text.contains("\r\nConnection: close\r\n"), "{text}");
}

#[test]
fn an_overlong_request_line_gets_414_and_the_connection_closes() {
    let (_server, addr) = start();
    let mut s = TcpStream::connect(&addr).unwrap();
    // 512 KiB of path and no line end: the old server waited for the end of the line.
    let mut w = s.try_clone().unwrap();
    let writer = std::thread::spawn(move || {
        let _ = w.write_all(b"GET /");
        let _ = w.write_all(&vec![b'a'; 512 << 10]);
    });
    let raw = read_until_closed(&mut s);
    writer.join().unwrap();
    assert_eq!(status_lines(&raw), ["HTTP/1.1 414 URI Too Long"]);
}

#[test]
fn keep_alive_requests_on_one_connection() {
    let (_server, addr) = start();
    let mut s = TcpStream::connect(&addr).unwrap();
    write!(
        s,
        "GET /style.css HTTP/1.1\r\nHost: {addr}\r\n\r\nHEAD / HTTP/1.1\r\nHost: {addr}\r\n\r\nGET /impax.js HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let raw = read_until_closed(&mut s);
    let statuses = status_lines(&raw);
    assert_eq!(
        statuses,
        ["HTTP/1.1 200 OK"; 3],
        "{}",
        String::from_utf8_lossy(&raw)
    );
    let (css, js) = (web("style.css"), web("impax.js"));
    assert!(raw.windows(css.len()).any(|w| w == css.as_slice()));
    assert!(raw.ends_with(&js), "the HEAD response has no body");
}

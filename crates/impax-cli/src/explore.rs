//! `impax explore`: the explorer page (`web/` of the repository, embedded in the binary) served
//! on 127.0.0.1, or written to a folder with `--out`.
//!
//! The page runs the impax core compiled to WebAssembly (`crates/impax-wasm`, built by
//! `scripts/build-explorer.sh` into `web/impax_wasm.wasm`). Besides the files of `web/`, the
//! page gets `impax_wasm.js`, the same module as base64 text, which the loader uses when
//! `fetch` is not allowed (a folder opened straight from the disk, `file://`).

use crate::cli::ExploreArgs;
use crate::input::{CliError, CliResult};
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::Path;
use std::time::Duration;

/// One file of the page.
pub struct Asset {
    /// Its name (the URL path without the leading `/`).
    pub name: &'static str,
    /// Its MIME type.
    pub mime: &'static str,
    /// Its bytes.
    pub bytes: &'static [u8],
}

/// The files of `web/`, embedded at build time.
pub const ASSETS: [Asset; 5] = [
    Asset {
        name: "index.html",
        mime: "text/html; charset=utf-8",
        bytes: include_bytes!("../../../web/index.html"),
    },
    Asset {
        name: "style.css",
        mime: "text/css; charset=utf-8",
        bytes: include_bytes!("../../../web/style.css"),
    },
    Asset {
        name: "impax.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../web/impax.js"),
    },
    Asset {
        name: "explorer.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../web/explorer.js"),
    },
    Asset {
        name: "impax_wasm.wasm",
        mime: "application/wasm",
        bytes: include_bytes!("../../../web/impax_wasm.wasm"),
    },
];

/// Name of the base64 copy of the module.
pub const WASM_JS: &str = "impax_wasm.js";

/// The module as a script that sets `IMPAX_WASM_BASE64`.
fn wasm_script() -> Vec<u8> {
    let wasm = ASSETS
        .iter()
        .find(|a| a.name == "impax_wasm.wasm")
        .map_or(&[][..], |a| a.bytes);
    format!(
        "// The impax core (WebAssembly) as base64, for pages opened from the disk.\nwindow.IMPAX_WASM_BASE64 = \"{}\";\n",
        base64(wasm)
    )
    .into_bytes()
}

/// Standard base64 with padding.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

pub fn run(args: &ExploreArgs, out: &mut Vec<u8>) -> CliResult<()> {
    match &args.out {
        Some(dir) => write_files(dir, out),
        None => serve(args.port),
    }
}

fn write_files(dir: &Path, out: &mut Vec<u8>) -> CliResult<()> {
    let fail =
        |e: std::io::Error| CliError::input(format!("--out {}: cannot write: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(fail)?;
    let script = wasm_script();
    let files = ASSETS
        .iter()
        .map(|a| (a.name, a.bytes))
        .chain(std::iter::once((WASM_JS, script.as_slice())));
    let mut n = 0;
    for (name, bytes) in files {
        std::fs::write(dir.join(name), bytes).map_err(fail)?;
        n += 1;
    }
    out.extend_from_slice(
        format!(
            "wrote {n} files to {}; open {} in a browser (no server needed)\n",
            dir.display(),
            dir.join("index.html").display()
        )
        .as_bytes(),
    );
    Ok(())
}

fn serve(port: u16) -> CliResult<()> {
    let listener = TcpListener::bind(("127.0.0.1", port)).map_err(|e| {
        CliError::input(format!(
            "--port {port}: cannot listen on 127.0.0.1:{port}: {e} (choose another port, or --port 0 for any free one)"
        ))
    })?;
    let addr = listener.local_addr().map_err(CliError::failure)?;
    {
        let mut stdout = std::io::stdout().lock();
        writeln!(stdout, "impax explorer: http://{addr}/  (Ctrl-C to stop)")
            .and_then(|_| stdout.flush())
            .map_err(CliError::failure)?;
    }
    let script: &'static [u8] = Box::leak(wasm_script().into_boxed_slice());
    for stream in listener.incoming() {
        let Ok(stream) = stream else { continue };
        // One thread per connection: a browser keeps idle connections open.
        std::thread::spawn(move || {
            let _ = answer(stream, script);
        });
    }
    Ok(())
}

/// The response to one request path: status, MIME type and body.
pub fn respond(
    method: &str,
    path: &str,
    script: &'static [u8],
) -> (u16, &'static str, &'static [u8]) {
    if method != "GET" && method != "HEAD" {
        return (405, "text/plain; charset=utf-8", b"only GET and HEAD\n");
    }
    let path = path.split(['?', '#']).next().unwrap_or("/");
    let name = path.trim_start_matches('/');
    let name = if name.is_empty() { "index.html" } else { name };
    if name == WASM_JS {
        return (200, "text/javascript; charset=utf-8", script);
    }
    match ASSETS.iter().find(|a| a.name == name) {
        Some(a) => (200, a.mime, a.bytes),
        None => (404, "text/plain; charset=utf-8", b"not found\n"),
    }
}

fn answer(stream: TcpStream, script: &'static [u8]) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(30)))?;
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut stream = stream;
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line)? == 0 {
            return Ok(());
        }
        let mut parts = line.split_whitespace();
        let (method, path) = (parts.next().unwrap_or(""), parts.next().unwrap_or("/"));
        let (method, path) = (method.to_string(), path.to_string());
        let mut keep_alive = line.contains("HTTP/1.1");
        // Headers up to the blank line.
        loop {
            let mut h = String::new();
            if reader.read_line(&mut h)? == 0 || h.trim().is_empty() {
                break;
            }
            let lower = h.to_ascii_lowercase();
            if lower.starts_with("connection:") && lower.contains("close") {
                keep_alive = false;
            }
        }
        let (status, mime, body) = respond(&method, &path, script);
        let reason = match status {
            200 => "OK",
            404 => "Not Found",
            _ => "Method Not Allowed",
        };
        let head = format!(
            "HTTP/1.1 {status} {reason}\r\nContent-Type: {mime}\r\nContent-Length: {}\r\nCache-Control: no-cache\r\nConnection: {}\r\n\r\n",
            body.len(),
            if keep_alive { "keep-alive" } else { "close" }
        );
        stream.write_all(head.as_bytes())?;
        if method != "HEAD" {
            stream.write_all(body)?;
        }
        stream.flush()?;
        if !keep_alive {
            return Ok(());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_known_values() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
        assert_eq!(base64(&[0xff, 0xfe, 0x00]), "//4A");
    }

    #[test]
    fn paths_and_types() {
        let s: &'static [u8] = b"x";
        assert_eq!(respond("GET", "/", s).1, "text/html; charset=utf-8");
        assert_eq!(respond("GET", "/impax_wasm.wasm", s).1, "application/wasm");
        assert_eq!(respond("GET", "/explorer.js?v=1", s).0, 200);
        assert_eq!(respond("GET", "/impax_wasm.js", s).2, b"x");
        assert_eq!(respond("GET", "/../Cargo.toml", s).0, 404);
        assert_eq!(respond("POST", "/", s).0, 405);
    }
}

//! `impax explore`: the explorer page (`web/` of the repository, embedded in the binary) served
//! on 127.0.0.1, or written to a folder with `--out`.
//!
//! The page runs the impax core compiled to WebAssembly (`crates/impax-wasm`, built by
//! `scripts/build-explorer.sh` into `web/impax_wasm.wasm`). Besides the files of `web/`, the
//! page gets `impax_wasm.js`, the same module as base64 text, which the loader uses when
//! `fetch` is not allowed (a folder opened straight from the disk, `file://`).

use crate::cli::ExploreArgs;
use crate::input::{CliError, CliResult};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
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
pub const ASSETS: [Asset; 9] = [
    Asset {
        name: "index.html",
        mime: "text/html; charset=utf-8",
        bytes: include_bytes!("../../../../web/index.html"),
    },
    Asset {
        name: "style.css",
        mime: "text/css; charset=utf-8",
        bytes: include_bytes!("../../../../web/style.css"),
    },
    Asset {
        name: "impax.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/impax.js"),
    },
    Asset {
        name: "views.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/views.js"),
    },
    Asset {
        name: "explorer.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/explorer.js"),
    },
    Asset {
        name: "multi.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/multi.js"),
    },
    Asset {
        name: "mechanism.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/mechanism.js"),
    },
    Asset {
        name: "conserved.js",
        mime: "text/javascript; charset=utf-8",
        bytes: include_bytes!("../../../../web/conserved.js"),
    },
    Asset {
        name: "impax_wasm.wasm",
        mime: "application/wasm",
        bytes: include_bytes!("../../../../web/impax_wasm.wasm"),
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
            let _ = connection(stream, script);
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

/// The longest request line or header line read, with its line end: a longer request line is
/// answered 414, a longer header line 431, and the connection closed.
pub const MAX_LINE: usize = 8 * 1024;

/// The longest request head (request line and headers) read: beyond it, 431 and close.
pub const MAX_HEAD: usize = 64 * 1024;

/// What the client may still send after a response that closes the connection, read and
/// discarded before closing (so that the response is not lost to a reset), in bytes.
const DRAIN_LIMIT: u64 = 1 << 20;

/// Serve one TCP connection: [`answer`] on the stream, then a graceful close.
fn connection(stream: TcpStream, script: &'static [u8]) -> std::io::Result<()> {
    // Each response is one write; without Nagle's delay it leaves at once (no wait for the
    // client's delayed acknowledgement of the previous one).
    stream.set_nodelay(true)?;
    stream.set_read_timeout(Some(Duration::from_secs(30)))?;
    let mut stream = stream;
    answer(&mut stream, script)?;
    // Closing with unread input would reset the connection, and a reset can discard the
    // response before the client reads it: end our side, then read (and drop) a bounded
    // amount of what the client still sends.
    stream.shutdown(Shutdown::Write)?;
    stream.set_read_timeout(Some(Duration::from_secs(2)))?;
    let _ = std::io::copy(&mut (&stream).take(DRAIN_LIMIT), &mut std::io::sink());
    Ok(())
}

/// One line of a request head.
enum Line {
    /// The line without its line end.
    Text(Vec<u8>),
    /// Longer than the limit (the rest is not read).
    TooLong,
    /// The input ended (before any byte of a line, or within one).
    End,
}

/// Read one line of at most `limit` bytes (line end included) from `reader`.
fn read_line<R: BufRead>(reader: &mut R, limit: usize) -> std::io::Result<Line> {
    let mut line = Vec::new();
    loop {
        let buf = reader.fill_buf()?;
        if buf.is_empty() {
            return Ok(Line::End);
        }
        let room = limit - line.len();
        let window = &buf[..buf.len().min(room)];
        if let Some(i) = window.iter().position(|&b| b == b'\n') {
            line.extend_from_slice(&window[..i]);
            reader.consume(i + 1);
            if line.last() == Some(&b'\r') {
                line.pop();
            }
            return Ok(Line::Text(line));
        }
        let n = window.len();
        line.extend_from_slice(window);
        reader.consume(n);
        if line.len() >= limit {
            return Ok(Line::TooLong);
        }
    }
}

/// One response: the status line, the headers and the body in one buffer.
fn response(status: u16, mime: &str, body: &[u8], head_only: bool, keep_alive: bool) -> Vec<u8> {
    let reason = match status {
        200 => "OK",
        400 => "Bad Request",
        404 => "Not Found",
        405 => "Method Not Allowed",
        414 => "URI Too Long",
        431 => "Request Header Fields Too Large",
        _ => "Error",
    };
    let allow = if status == 405 {
        "Allow: GET, HEAD\r\n"
    } else {
        ""
    };
    let mut out = format!(
        "HTTP/1.1 {status} {reason}\r\n{allow}Content-Type: {mime}\r\nContent-Length: {}\r\nCache-Control: no-cache\r\nConnection: {}\r\n\r\n",
        body.len(),
        if keep_alive { "keep-alive" } else { "close" }
    )
    .into_bytes();
    if !head_only {
        out.extend_from_slice(body);
    }
    out
}

/// An error response that closes the connection.
fn refuse<W: Write>(stream: &mut W, status: u16, text: &str) -> std::io::Result<()> {
    let body = format!("{text}\n");
    stream.write_all(&response(
        status,
        "text/plain; charset=utf-8",
        body.as_bytes(),
        false,
        false,
    ))?;
    stream.flush()
}

/// Answer the requests of one connection until it closes or a response closes it.
///
/// The head of each request is read line by line, at most [`MAX_LINE`] bytes a line and
/// [`MAX_HEAD`] in all (414 or 431 beyond, and close, without reading further). Only `GET`
/// and `HEAD` are served; any other method gets 405 with `Allow: GET, HEAD` and the
/// connection is closed, so a request body is never read as a request; so is a `GET` that
/// announces a body (answered, then closed). Each response is written with one `write_all`.
pub fn answer<S: Read + Write>(stream: &mut S, script: &'static [u8]) -> std::io::Result<()> {
    let mut reader = BufReader::new(stream);
    loop {
        let line = match read_line(&mut reader, MAX_LINE)? {
            Line::Text(line) if line.is_empty() => continue, // a stray CRLF between requests
            Line::Text(line) => line,
            Line::End => return Ok(()),
            Line::TooLong => {
                return refuse(
                    reader.get_mut(),
                    414,
                    &format!("request line longer than {MAX_LINE} bytes"),
                )
            }
        };
        let mut head_bytes = line.len();
        let line = String::from_utf8_lossy(&line).into_owned();
        let parts: Vec<&str> = line.split_whitespace().collect();
        let [method, path, version] = parts[..] else {
            return refuse(reader.get_mut(), 400, "malformed request line");
        };
        if !version.starts_with("HTTP/1.") {
            return refuse(reader.get_mut(), 400, "not an HTTP/1.x request");
        }
        let mut keep_alive = version == "HTTP/1.1";
        let mut has_body = false;
        // Headers up to the blank line.
        loop {
            let h = match read_line(&mut reader, MAX_LINE)? {
                Line::Text(h) => h,
                Line::End => return Ok(()),
                Line::TooLong => {
                    return refuse(
                        reader.get_mut(),
                        431,
                        &format!("header line longer than {MAX_LINE} bytes"),
                    )
                }
            };
            if h.is_empty() {
                break;
            }
            head_bytes += h.len();
            if head_bytes > MAX_HEAD {
                return refuse(
                    reader.get_mut(),
                    431,
                    &format!("request head longer than {MAX_HEAD} bytes"),
                );
            }
            let h = String::from_utf8_lossy(&h).to_ascii_lowercase();
            let (name, value) = h.split_once(':').unwrap_or((&h, ""));
            match (name.trim(), value.trim()) {
                ("connection", v) if v.contains("close") => keep_alive = false,
                ("connection", v) if v.contains("keep-alive") => keep_alive = true,
                ("content-length", v) => has_body |= v != "0",
                ("transfer-encoding", _) => has_body = true,
                _ => {}
            }
        }
        if method != "GET" && method != "HEAD" {
            return refuse(reader.get_mut(), 405, "only GET and HEAD");
        }
        // The body of a GET is not read: close after the response rather than read it as
        // the next request.
        keep_alive &= !has_body;
        let (status, mime, body) = respond(method, path, script);
        let stream = reader.get_mut();
        stream.write_all(&response(status, mime, body, method == "HEAD", keep_alive))?;
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

    /// An in-memory connection: `input` then `filler` bytes up to `filler_len` (an endless
    /// request line or header), counting the bytes read and the write calls.
    struct Duplex {
        input: std::io::Cursor<Vec<u8>>,
        filler: u8,
        filler_len: u64,
        read: u64,
        writes: usize,
        output: Vec<u8>,
    }

    impl Duplex {
        fn new(input: &[u8]) -> Self {
            Self::endless(input, b'x', 0)
        }

        fn endless(input: &[u8], filler: u8, filler_len: u64) -> Self {
            Self {
                input: std::io::Cursor::new(input.to_vec()),
                filler,
                filler_len,
                read: 0,
                writes: 0,
                output: Vec::new(),
            }
        }

        fn run(mut self) -> Self {
            answer(&mut self, b"x").unwrap();
            self
        }

        fn text(&self) -> String {
            String::from_utf8_lossy(&self.output).into_owned()
        }

        fn responses(&self) -> usize {
            self.text().matches("HTTP/1.1 ").count()
        }
    }

    impl Read for Duplex {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            let mut n = self.input.read(buf)?;
            if n == 0 {
                let left = self.filler_len - (self.read - self.input.get_ref().len() as u64);
                n = buf.len().min(left.min(4096) as usize);
                buf[..n].fill(self.filler);
            }
            self.read += n as u64;
            Ok(n)
        }
    }

    impl Write for Duplex {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.writes += 1;
            self.output.extend_from_slice(buf);
            Ok(buf.len())
        }

        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    const GIB: u64 = 1 << 30;

    #[test]
    fn each_response_is_one_write() {
        // Head and body written separately made every keep-alive request after the first
        // wait for the client's delayed acknowledgement (Nagle): one buffer, one write.
        let c = Duplex::new(
            b"GET / HTTP/1.1\r\nHost: a\r\n\r\nGET /style.css HTTP/1.1\r\nHost: a\r\n\r\nHEAD /impax.js HTTP/1.1\r\nConnection: close\r\n\r\n",
        )
        .run();
        assert_eq!(c.responses(), 3, "{}", c.text());
        assert_eq!(c.writes, 3);
        let index = &ASSETS[0];
        assert!(c
            .output
            .windows(index.bytes.len())
            .any(|w| w == index.bytes));
        assert!(
            c.text().ends_with("Connection: close\r\n\r\n"),
            "HEAD has no body"
        );
    }

    #[test]
    fn an_endless_request_line_gets_414_after_a_bounded_read() {
        // A 200 MB request line was buffered whole.
        let c = Duplex::endless(b"GET /", b'a', GIB).run();
        assert!(
            c.text().starts_with("HTTP/1.1 414 URI Too Long\r\n"),
            "{}",
            c.text()
        );
        assert!(c.text().contains("Connection: close\r\n"));
        assert_eq!(c.responses(), 1);
        assert!(c.read <= (MAX_LINE + 8192) as u64, "read {} bytes", c.read);
    }

    #[test]
    fn an_endless_header_gets_431_after_a_bounded_read() {
        let c = Duplex::endless(b"GET / HTTP/1.1\r\nX-Long: ", b'a', GIB).run();
        assert!(c.text().starts_with("HTTP/1.1 431 "), "{}", c.text());
        assert_eq!(c.responses(), 1);
        assert!(c.read <= (MAX_LINE + 8192) as u64, "read {} bytes", c.read);
    }

    #[test]
    fn endless_headers_get_431_after_a_bounded_read() {
        // Short header lines without end: the head as a whole is bounded.
        let mut head = b"GET / HTTP/1.1\r\n".to_vec();
        for k in 0..100_000 {
            head.extend_from_slice(format!("X-{k}: {}\r\n", "b".repeat(100)).as_bytes());
        }
        let c = Duplex::new(&head).run();
        assert!(c.text().starts_with("HTTP/1.1 431 "), "{}", c.text());
        assert_eq!(c.responses(), 1);
        assert!(
            c.read <= (MAX_HEAD + MAX_LINE + 8192) as u64,
            "read {} bytes",
            c.read
        );
    }

    #[test]
    fn a_post_body_is_not_read_as_a_request() {
        // The body of a POST (here a whole GET request) was parsed as a second request.
        let body = b"GET /style.css HTTP/1.1\r\nHost: a\r\n\r\n";
        let mut input = format!(
            "POST / HTTP/1.1\r\nHost: a\r\nContent-Length: {}\r\n\r\n",
            body.len()
        )
        .into_bytes();
        input.extend_from_slice(body);
        let c = Duplex::new(&input).run();
        assert_eq!(c.responses(), 1, "{}", c.text());
        assert!(c.text().starts_with("HTTP/1.1 405 Method Not Allowed\r\n"));
        assert!(c.text().contains("\r\nAllow: GET, HEAD\r\n"));
        assert!(c.text().contains("\r\nConnection: close\r\n"));
        assert_eq!(c.writes, 1);
    }

    #[test]
    fn a_get_with_a_body_is_answered_then_closed() {
        let c = Duplex::new(
            b"GET /style.css HTTP/1.1\r\nContent-Length: 16\r\n\r\nGET / HTTP/1.1\r\n\r\n",
        )
        .run();
        assert_eq!(c.responses(), 1, "{}", c.text());
        assert!(c.text().starts_with("HTTP/1.1 200 OK\r\n"));
        assert!(c.text().contains("Content-Type: text/css"));
        assert!(c.text().contains("\r\nConnection: close\r\n"));
    }

    #[test]
    fn a_malformed_request_line_gets_400() {
        let c = Duplex::new(b"hello\r\n\r\n").run();
        assert!(
            c.text().starts_with("HTTP/1.1 400 Bad Request\r\n"),
            "{}",
            c.text()
        );
        assert_eq!(c.responses(), 1);
    }
}

//! # impax-wasm — the impax core for the explorer page
//!
//! The explorer page (`web/`, served by `impax explore`) runs this crate compiled to
//! `wasm32-unknown-unknown`. Every number the page shows comes from here, that is from the
//! same library code as the `impax` command line; the page's JavaScript only draws.
//!
//! ## The interface
//! Plain C-ABI exports, no bindings generator. A request is JSON text written into the
//! module's memory; the answer is JSON text in a buffer the module keeps until the next call:
//!
//! 1. `impax_alloc(len) -> ptr`: room for a request of `len` bytes;
//! 2. write the UTF-8 request at `ptr`;
//! 3. `impax_compare(ptr, len)`, `impax_multi(ptr, len)`, `impax_mechanism(ptr, len)`,
//!    `impax_conserved(ptr, len)` or `impax_map(ptr, len)` (which also free the request)
//!    returns a pointer to the answer, `impax_output_len()` its length in bytes;
//! 4. `impax_map` also leaves the map's cells in two arrays: `impax_map_values()`
//!    (`f32` per cell: `ΔT/T0`, NaN where the law broke down or the point is invalid) and
//!    `impax_map_classes()` (`u8` per cell, see [`map::Class`]), `nx × ny` cells, row by row
//!    from the lowest `y`.
//!
//! A bad request is answered with `{"error": "one line"}`, never a trap. The Rust functions
//! behind the exports, [`compare_json`], [`multi_json`], [`mechanism_json`],
//! [`conserved_json`] and [`map_json`], are public for tests on the host.
//!
//! ## Example
//! ```
//! let answer = impax_wasm::compare_json(
//!     r#"{"friction": 0.4, "restitution": 0.7,
//!         "body": {"shape": "sphere", "mass": 1, "radius": 1,
//!                  "speed": 1, "alpha_deg": 30, "spin_ratio": 0}}"#,
//! );
//! let v: serde_json::Value = serde_json::from_str(&answer).unwrap();
//! let whittaker = &v["results"][0];
//! assert_eq!(whittaker["law"], "whittaker");
//! assert!(whittaker["energy_change_ratio"].as_f64().unwrap() > 0.0); // Kane's paradox
//! ```

#![warn(missing_docs)]

pub mod animation;
pub mod case;
pub mod conserved;
pub mod map;
pub mod mechanism;
pub mod multi;
pub mod report;

use std::cell::RefCell;

/// Answer a compare request (see [`case::Request`]) with every law's result as JSON
/// (see [`report::compare`]), or `{"error": …}`.
pub fn compare_json(request: &str) -> String {
    let answer = serde_json::from_str::<case::Request>(request)
        .map_err(|e| format!("request: {e}"))
        .and_then(|r| report::compare(&r));
    finish(answer)
}

/// Answer a request of the view with several contacts (see [`multi::system::MultiRequest`]:
/// a built-in system, its parameters, μ and e) with every multi-contact law's result, the
/// scene and each law's motion after the impact (see [`multi`]), or `{"error": …}`.
///
/// ```
/// let answer = impax_wasm::multi_json(r#"{"system": "cradle", "balls": 3}"#);
/// let v: serde_json::Value = serde_json::from_str(&answer).unwrap();
/// let lcp = &v["results"][0];
/// assert_eq!(lcp["law"], "lcp");
/// let first = lcp["velocities_after"][0].as_f64().unwrap();
/// assert!((first + 1.0 / 3.0).abs() < 1e-12); // the LCP's cradle: (−1/3, 2/3, 2/3) v0
/// ```
pub fn multi_json(request: &str) -> String {
    let answer = serde_json::from_str::<multi::system::MultiRequest>(request)
        .map_err(|e| format!("request: {e}"))
        .and_then(|r| multi::answer(&r));
    finish(answer)
}

/// Answer a request of the view "Your mechanism" (see [`mechanism::MechanismRequest`]: a
/// mechanism file's text, optionally `q`, `u`, μ and e) with every law on the impact of the
/// contact that strikes, as `impax compare FILE --json` (see [`mechanism`]), or
/// `{"error": …}` saying where in the file.
///
/// ```
/// let file = include_str!("../../../examples/mechanisms/double-pendulum.toml");
/// let request = serde_json::json!({ "file": file }).to_string();
/// let v: serde_json::Value = serde_json::from_str(&impax_wasm::mechanism_json(&request)).unwrap();
/// let whittaker = &v["results"][0];
/// assert_eq!(whittaker["verdict"], "energy-gained"); // Kane's paradox, from the file
/// let bad = serde_json::json!({ "file": file.replace("parent = \"rod 1\"", "parent = \"rod 3\"") });
/// let v: serde_json::Value =
///     serde_json::from_str(&impax_wasm::mechanism_json(&bad.to_string())).unwrap();
/// assert!(v["error"].as_str().unwrap().starts_with("line 36: joint[theta2].parent: "));
/// ```
pub fn mechanism_json(request: &str) -> String {
    let answer = serde_json::from_str::<mechanism::MechanismRequest>(request)
        .map_err(|e| format!("request: {e}"))
        .and_then(|r| mechanism::answer(&r));
    finish(answer)
}

/// Answer a request of the view of conserved quantities (a built-in mechanism, its
/// parameters and state, and the run's options; see [`conserved`]) with every quantity the
/// tracker reports over time, as `impax conserved NAME --json`, and the bodies' poses, or
/// `{"error": …}`.
///
/// ```
/// let v: serde_json::Value =
///     serde_json::from_str(&impax_wasm::conserved_json(r#"{"mechanism": "ring-pendulum"}"#))
///         .unwrap();
/// let q = |name: &str| v["quantities"].as_array().unwrap().iter().find(|q| q["name"] == name).unwrap().clone();
/// assert_eq!(q("p_x")["conserved"], true); // x is cyclic
/// assert_eq!(q("P_x")["conserved"], false); // the rolling contact pushes
/// assert_eq!(q("boost x")["conserved"], true);
/// ```
pub fn conserved_json(request: &str) -> String {
    finish(conserved::answer(request))
}

/// Answer a map request (see [`map::MapRequest`]): the map's description as JSON, the cells
/// in `values` and `classes` (cleared and refilled), or `{"error": …}`.
pub fn map_json(request: &str, values: &mut Vec<f32>, classes: &mut Vec<u8>) -> String {
    let answer = serde_json::from_str::<map::MapRequest>(request)
        .map_err(|e| format!("request: {e}"))
        .and_then(|r| map::compute(&r, values, classes));
    finish(answer)
}

/// The laws and bodies the module knows, as JSON: `{"version", "laws", "mechanism_laws",
/// "spatial_laws", "multi_laws", "shapes", "shape_parameters", "map_parameters",
/// "multi_systems", "mechanism_files", "conserved_systems"}`. `mechanism_files` are the files
/// of `examples/mechanisms/` (`{"name", "text"}`, embedded at build time);
/// `conserved_systems` the view of conserved quantities' mechanisms with their defaults
/// ([`conserved::systems_json`]).
/// `multi_systems` gives each system of the view with several contacts its parameters with
/// the core's defaults, its default μ and e ([`multi::system::systems_json`]). `shape_parameters` gives, for each shape,
/// its numbers as the core's table names them: `{"name"` (e.g. `semi_axis_a`), `"key"` and
/// `"index"` (where it goes in a request: `semi_axes[0]`; `index` null for a single number),
/// `"label"`, `"quantity"` (`length`, `angle`, `inertia` or `offset`)`}`.
pub fn info_json() -> String {
    let laws: Vec<&str> = impax::LawId::ALL.iter().map(|l| l.as_str()).collect();
    let mech: Vec<&str> = impax::LawId::CONTACT_SPACE
        .iter()
        .map(|l| l.as_str())
        .collect();
    let multi_laws: Vec<&str> = impax::LawId::MULTI_CONTACT
        .iter()
        .map(|l| l.as_str())
        .collect();
    serde_json::json!({
        "version": env!("CARGO_PKG_VERSION"),
        "laws": laws,
        "mechanism_laws": mech,
        "multi_laws": multi_laws,
        "shapes": case::SHAPES,
        "shape_parameters": case::shape_parameters(),
        "map_parameters": {
            "body": case::BODY_PARAMETERS,
            "mechanism": case::MECHANISM_PARAMETERS,
        },
        "multi_systems": multi::system::systems_json(),
        "mechanism_files": mechanism::examples_json(),
        "conserved_systems": conserved::systems_json(),
        "spatial_laws": impax::LawId::SPATIAL.map(|l| l.as_str()),
    })
    .to_string()
}

fn finish(answer: Result<serde_json::Value, String>) -> String {
    match answer {
        Ok(v) => v.to_string(),
        Err(e) => serde_json::json!({ "error": e.replace('\n', " ") }).to_string(),
    }
}

// ---- the C-ABI exports -------------------------------------------------------------------

thread_local! {
    static OUTPUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    static MAP_VALUES: RefCell<Vec<f32>> = const { RefCell::new(Vec::new()) };
    static MAP_CLASSES: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
}

/// Keep `text` as the current answer and return a pointer to it.
fn keep(text: String) -> *const u8 {
    OUTPUT.with(|o| {
        let mut o = o.borrow_mut();
        *o = text.into_bytes();
        o.as_ptr()
    })
}

/// Read a request of `len` bytes at `ptr` (allocated by [`impax_alloc`]) and free it.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and not be freed yet.
unsafe fn take_request(ptr: *mut u8, len: usize) -> Result<String, String> {
    if ptr.is_null() {
        return Err("request: null pointer".into());
    }
    // SAFETY: the caller passes a buffer from `impax_alloc(len)`, whose capacity is `len`.
    let bytes = unsafe { Vec::from_raw_parts(ptr, len, len) };
    String::from_utf8(bytes).map_err(|_| "request: not UTF-8 text".into())
}

/// Allocate `len` bytes for a request (freed by the call that reads it, or by
/// [`impax_free`]).
#[no_mangle]
pub extern "C" fn impax_alloc(len: usize) -> *mut u8 {
    let mut v = vec![0u8; len];
    let ptr = v.as_mut_ptr();
    std::mem::forget(v);
    ptr
}

/// Free a buffer from [`impax_alloc`] that was not passed to a call.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and not be freed yet.
#[no_mangle]
pub unsafe extern "C" fn impax_free(ptr: *mut u8, len: usize) {
    if !ptr.is_null() {
        // SAFETY: as documented, `ptr` is a live allocation of `impax_alloc(len)`.
        drop(unsafe { Vec::from_raw_parts(ptr, len, len) });
    }
}

/// Length in bytes of the last answer.
#[no_mangle]
pub extern "C" fn impax_output_len() -> usize {
    OUTPUT.with(|o| o.borrow().len())
}

/// The module's laws, shapes and map parameters ([`info_json`]).
#[no_mangle]
pub extern "C" fn impax_info() -> *const u8 {
    keep(info_json())
}

/// Every law on one impact ([`compare_json`]); the request is freed.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and hold the request; it is freed here.
#[no_mangle]
pub unsafe extern "C" fn impax_compare(ptr: *mut u8, len: usize) -> *const u8 {
    // SAFETY: forwarded from the caller's contract.
    let answer = match unsafe { take_request(ptr, len) } {
        Ok(text) => compare_json(&text),
        Err(e) => finish(Err(e)),
    };
    keep(answer)
}

/// Every multi-contact law on a built-in system ([`multi_json`]); the request is freed.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and hold the request; it is freed here.
#[no_mangle]
pub unsafe extern "C" fn impax_multi(ptr: *mut u8, len: usize) -> *const u8 {
    // SAFETY: forwarded from the caller's contract.
    let answer = match unsafe { take_request(ptr, len) } {
        Ok(text) => multi_json(&text),
        Err(e) => finish(Err(e)),
    };
    keep(answer)
}

/// Every law on a mechanism file's impact ([`mechanism_json`]); the request is freed.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and hold the request; it is freed here.
#[no_mangle]
pub unsafe extern "C" fn impax_mechanism(ptr: *mut u8, len: usize) -> *const u8 {
    // SAFETY: forwarded from the caller's contract.
    let answer = match unsafe { take_request(ptr, len) } {
        Ok(text) => mechanism_json(&text),
        Err(e) => finish(Err(e)),
    };
    keep(answer)
}

/// The conserved quantities along a built-in's free motion ([`conserved_json`]); the
/// request is freed.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and hold the request; it is freed here.
#[no_mangle]
pub unsafe extern "C" fn impax_conserved(ptr: *mut u8, len: usize) -> *const u8 {
    // SAFETY: forwarded from the caller's contract.
    let answer = match unsafe { take_request(ptr, len) } {
        Ok(text) => conserved_json(&text),
        Err(e) => finish(Err(e)),
    };
    keep(answer)
}

/// An energy map over two parameters for one law ([`map_json`]); the request is freed.
///
/// # Safety
/// `ptr` must come from `impax_alloc(len)` and hold the request; it is freed here.
#[no_mangle]
pub unsafe extern "C" fn impax_map(ptr: *mut u8, len: usize) -> *const u8 {
    // SAFETY: forwarded from the caller's contract.
    let answer = match unsafe { take_request(ptr, len) } {
        Ok(text) => MAP_VALUES.with(|v| {
            MAP_CLASSES.with(|c| map_json(&text, &mut v.borrow_mut(), &mut c.borrow_mut()))
        }),
        Err(e) => finish(Err(e)),
    };
    keep(answer)
}

/// The `f32` cells of the last map (`ΔT/T0`, NaN where there is none).
#[no_mangle]
pub extern "C" fn impax_map_values() -> *const f32 {
    MAP_VALUES.with(|v| v.borrow().as_ptr())
}

/// The `u8` class of each cell of the last map ([`map::Class`]).
#[no_mangle]
pub extern "C" fn impax_map_classes() -> *const u8 {
    MAP_CLASSES.with(|c| c.borrow().as_ptr())
}

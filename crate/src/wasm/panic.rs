//! The crash path: a panic in the core is reported with its message to the console and to the
//! listener given to [`on_panic`] before the call traps, so the studio can say what failed and
//! start a fresh core.

use std::cell::RefCell;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = console, js_name = error)]
    fn console_error(message: &str);
}

thread_local! {
    /// Told the message of a panic (see [`on_panic`]).
    static PANIC_LISTENER: RefCell<Option<js_sys::Function>> = const { RefCell::new(None) };
}

/// Installs the panic hook when the module starts: a panic's message goes to the console and to
/// the [`on_panic`] listener before the call traps.
#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        let message = format!("the core crashed (a bug): {info}");
        console_error(&message);
        PANIC_LISTENER.with(|listener| {
            if let Ok(listener) = listener.try_borrow() {
                if let Some(f) = listener.as_ref() {
                    let _ = f.call1(&JsValue::NULL, &JsValue::from_str(&message));
                }
            }
        });
    }));
}

/// Calls `listener(message)` when the core panics, just before the call that panicked throws
/// (a `WebAssembly.RuntimeError`). The instance should not be used after that.
#[wasm_bindgen(js_name = onPanic)]
pub fn on_panic(listener: js_sys::Function) {
    PANIC_LISTENER.with(|l| *l.borrow_mut() = Some(listener));
}

/// Panics with `message`: how the tests reach the panic path (the hook, [`on_panic`], the studio's
/// `CoreCrashed`) now that no known input does.
#[wasm_bindgen(js_name = panicForTests)]
pub fn panic_for_tests(message: &str) {
    panic!("{message}");
}

//! [`DrawError`]: a render refused, or a display driver failed.

use core::fmt;

use crate::error::Error;

/// Why drawing on a display stopped: fixray refused the request, or the display driver
/// returned an error, which is handed back unchanged. Every fixray call that draws on a
/// display returns it; it converts from [`Error`], so `?` joins set-up and drawing.
///
/// `E` is the driver's [`DrawTarget::Error`](embedded_graphics::draw_target::DrawTarget::Error).
/// Rows already sent before the failure stay on the display; nothing is retried.
///
/// ```
/// use fixray::{DrawError, Error};
/// let refused: DrawError<u8> = Error::NonPositiveRadius.into();
/// assert_eq!(refused, DrawError::Render(Error::NonPositiveRadius));
/// let driver: DrawError<&str> = DrawError::Display("SPI timeout");
/// assert_eq!(driver.to_string(), "display driver error: \"SPI timeout\"");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DrawError<E> {
    /// fixray refused the request: rows outside the picture, a row buffer shorter than a
    /// row.
    Render(Error),
    /// The display driver's own error, as it returned it.
    Display(E),
}

impl<E> From<Error> for DrawError<E> {
    fn from(e: Error) -> Self {
        DrawError::Render(e)
    }
}

impl<E: fmt::Debug> fmt::Display for DrawError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DrawError::Render(e) => write!(f, "{e}"),
            DrawError::Display(e) => write!(f, "display driver error: {e:?}"),
        }
    }
}

impl<E: fmt::Debug> core::error::Error for DrawError<E> {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            DrawError::Render(e) => Some(e),
            DrawError::Display(_) => None,
        }
    }
}

//! Moving diagnostics from a shader's own text onto the file that holds it: every span (the
//! primary one, the secondary labels', the fix's edits) shifted by the shader's offset there.

use essl::diagnostic::Diagnostic;

/// Shifts every span of `diagnostics` by `by` bytes.
pub(crate) fn relocate(diagnostics: &mut [Diagnostic], by: u32) {
    for s in diagnostics.iter_mut().flat_map(Diagnostic::spans_mut) {
        s.start += by;
        s.end += by;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic::Fix;
    use essl::diagnostic_code::Code;
    use essl::source::Span;

    #[test]
    fn every_span_moves() {
        let mut d = [
            Diagnostic::error(Code::MissingSemicolon, "m", Span::new(3, 4))
                .with_secondary(Span::new(0, 1), "here")
                .with_fix(Fix::certain("insert `;`", Span::new(4, 4), ";")),
        ];
        relocate(&mut d, 10);
        assert_eq!(d[0].span, Span::new(13, 14));
        assert_eq!(d[0].secondary[0].span, Span::new(10, 11));
        assert_eq!(d[0].fix.as_ref().unwrap().edits[0].span, Span::new(14, 14));
    }
}

// The demo under Trusted Types (`require-trusted-types-for 'script'`). The demo's own code sets no
// HTML from strings, but lil-gui (three's copy) writes every folder title, control name and option
// with innerHTML. The default policy below is what such a string assignment then goes through: it
// lets plain text pass, where innerHTML = text means what textContent = text would, and refuses
// anything with markup or an entity (the assignment then throws and a violation is reported).
// Without Trusted Types in the browser it does nothing.

/** Text whose HTML parse is itself: no tags, no entities. */
const PLAIN_TEXT = /^[^<&]*$/;

/**
 * Creates the page's default Trusted Types policy, once, before the panel is built.
 * @returns {boolean} whether one was created (false where the browser has no Trusted Types)
 */
export function allowPlainTextHtml() {
  const { trustedTypes } = window;
  if (!trustedTypes?.createPolicy || trustedTypes.defaultPolicy) return false;
  trustedTypes.createPolicy('default', {
    createHTML: (text) => (PLAIN_TEXT.test(text) ? text : null),
  });
  return true;
}

// `haven serve`: once a page is done with (a trial and its questionnaires, the instruments), the
// participant's browser goes back to their session page, saying which page it leaves (its token),
// so that page is never handed out to them again.
export const GO_ON_MS = 2500; // time to read the last words on the page

export function goOn(nextUrl) {
  if (!nextUrl || goOn.started) return false;
  goOn.started = true;
  const token = new URLSearchParams(location.search).get("token") || "";
  const sep = nextUrl.includes("?") ? "&" : "?";
  setTimeout(() => location.assign(`${nextUrl}${sep}left=${encodeURIComponent(token)}`), GO_ON_MS);
  return true;
}

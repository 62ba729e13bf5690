// Injected into a copy of report.html by tests/cli_report_html.sh: once the
// page and its images loaded, writes one line into the page (read back with
// chromium --dump-dom): every image decoded (naturalWidth > 0) and every
// in-page link (#id) pointing at an element that exists.
window.addEventListener('load', function () {
  var bad = [];
  for (var i = 0; i < document.images.length; i++) {
    var img = document.images[i];
    if (!img.complete || img.naturalWidth === 0) bad.push('image ' + img.getAttribute('src'));
  }
  var links = document.querySelectorAll('a[href^="#"]');
  for (var j = 0; j < links.length; j++) {
    var id = decodeURIComponent(links[j].getAttribute('href').slice(1));
    if (!document.getElementById(id)) bad.push('link #' + id);
  }
  var pre = document.createElement('pre');
  pre.textContent = 'NL-' + 'PROBE images=' + document.images.length + ' links=' + links.length +
                    (bad.length ? ' BROKEN: ' + bad.join(', ') : ' OK');
  document.body.appendChild(pre);
});

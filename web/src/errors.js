// Every error the page meets, as text: uncaught exceptions (also those of event handlers),
// rejected promises and console.error calls (three.js reports a failed shader there).
export function recordErrors() {
  const errors = [];
  window.addEventListener('error', (event) => errors.push(String(event.message)));
  window.addEventListener('unhandledrejection', (event) => errors.push(`unhandled rejection: ${event.reason}`));
  const consoleError = console.error.bind(console);
  console.error = (...args) => {
    errors.push(args.map(String).join(' '));
    consoleError(...args);
  };
  return errors;
}

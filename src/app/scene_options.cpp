// Shared scene options (being written in issue 2).
